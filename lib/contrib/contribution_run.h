// rcontrib's run, shared by rcontrib and rfluxmtx: its command line (rtrace's options that apply, and the
// modifiers with their bins, definitions and parameters, formats, outputs) and the loop that reads rays,
// traces each record's rays with a tally of its own (on every thread, records in input order) and writes the
// records.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "contrib/modifier_bins.h"
#include "integrator/render_options.h"
#include "render/shared_bounces.h"
#include "util/options.h"

namespace brume {

struct ContributionRun {
    ProgramOptions program;
    RenderSettings render;
    bool irradiance = false, irradianceAtHit = false, header = true, values = false, overwrite = false;
    int accumulate = 1, xres = 0, yres = 0;
    // -aS: first bounces within this fraction of their distance from the query share their continuations
    // (shared_bounces.h); 0: each its own path, as Radiance's.
    double shareBounces = kShareBouncesDefault;
    char inFormat = 'a', outFormat = 'a';
    std::vector<CalDefinition> definitions;
    std::vector<ModifierRequest> modifiers;
    ModifierRequest next;  // the -b, -bn, -p and -o the next -m takes

    void addModifier(const std::string& name);
};

// The options of rcontrib's command line, applied to `run` as they are parsed.
OptionTable contributionOptions(ContributionRun& run);
// parseCommandLine for a table made by contributionOptions (and more options of a program's own): rcontrib's
// -f names a function file where the word is -f alone, formats where letters follow it.
std::optional<CommandLine> parseContributionCommandLine(int argc, char** argv, const OptionTable& table,
                                                        const ProgramOptions& program, const std::string& usage,
                                                        const std::string& features);

// Where a run's rays come from: the next ray's origin and direction in `ray`, false at the end. The standard
// input's (a RayReader) or rfluxmtx's sender's.
using RayStream = std::function<bool(std::array<double, 6>& ray)>;

// Traces the records of rays from `rays` in `sceneFiles` (octrees and scene files), and writes them where
// `run` says; `command` names the run in the output's header. Throws Error for what cannot be told (media),
// bad rays, outputs that cannot be written (removed then).
void runContributions(ContributionRun run, const std::vector<std::string>& sceneFiles,
                      const std::vector<std::string>& command, const RayStream& rays);

}  // namespace brume
