// The rendering options rtrace and rpict share (-a*, -d*, -l*, -s*, -bv, -u, -i), declared once.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "integrator/settings.h"
#include "spectrum/color_output.h"
#include "util/options.h"

namespace brume {

// Registers the options that set `settings`; `irradianceAtHit` receives -i.
void addRenderOptions(OptionTable& table, RenderSettings& settings, bool& irradianceAtHit);

// The output colour options: -pRGB, -pXYZ and -pc (primaries) for both programs; with `values` (rtrace)
// also -pY, -pS, -pM, -pMD65, -pA (one value) and -co (the spectrum). The last one given wins.
void addColorOutputOptions(OptionTable& table, ColorOutput& output, bool values);

// Radiance's rpict defaults, where they differ from rtrace's (fewer, coarser samples for pictures).
void usePictureDefaults(RenderSettings& settings);

// What every rendering program takes besides: -w, -n, -e, and -defaults -help -version -features, which
// print and stop (recorded in `immediate`).
struct ProgramOptions {
    std::string immediate;
    bool warnings = true;
    int threads = 0;  // 0: one per hardware thread
};
void addProgramOptions(OptionTable& table, ProgramOptions& options);
// A rendering program's command line: the command as its output header names it (program and options) and
// the scene files after the options.
struct CommandLine {
    std::vector<std::string> command, scene;
};
// Sets the program name, parses argv with `table` ("--help" taken as -help) and applies -w. Prints what an
// immediate option asks for (usage, version, defaults, `features`) and returns nullopt, so the program
// stops; throws Error after the usage when no scene is named.
std::optional<CommandLine> parseCommandLine(int argc, char** argv, const OptionTable& table, const ProgramOptions& options,
                                            const std::string& usage, const std::string& features);
// Every option that changes cached values, as text (with Brume's version): a cache file made with other
// options is refused. Not -T: records keep their own instant.
std::string cacheOptions(const RenderSettings& settings);

// Refuses settings that cannot work together.
void checkRenderSettings(const RenderSettings& settings);

}  // namespace brume
