// What the annual-daylight fuzz target does with an input (see README.md): the first byte picks a weather
// tape ('w': read every record and make its sky, every value finite), an rfluxmtx file ('r': its surfaces and settings
// read, and as a sender each bin's first rays finite, unit and leaving into the side away from its normal) or a
// matrix ('m': read it, transpose it, multiply it by the transpose, write it); Error is fine, a value that is
// not finite a bug.
#pragma once
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "contrib/flux_surfaces.h"
#include "contrib/senders.h"
#include "matrix/matrix_file.h"
#include "sky/sky_matrix.h"
#include "util/error.h"

namespace brume {

// An rfluxmtx file's surfaces and settings, and as a sender its bins' first rays.
inline bool exerciseFluxFile(const std::string& text) {
    std::string path = (std::filesystem::temp_directory_path() / ("brume_fuzz_flux_" + std::to_string(::getpid()) + ".rad")).string();
    std::ofstream(path) << text;
    bool ok = true;
    try {
        FluxSettings settings;
        for (const FluxSurface& s : readFluxSurfaces(path, "receiver")) {
            for (const auto& [at, words] : s.settings) applyFluxSettings(words, settings, at);
            glm::dvec3 up = upOf(settings, s.normal);
            ok = ok && std::isfinite(s.area) && std::isfinite(glm::length(s.normal)) && std::isfinite(glm::length(up));
        }
    } catch (const Error&) {
    }
    try {
        Sender sender(path);
        for (int b = 0; b < sender.bins() && b < 200; ++b)
            for (uint32_t i = 0; i < 4; ++i) {
                std::array<double, 6> r = sender.ray(b, i, 1);
                for (double v : r) ok = ok && std::isfinite(v);
                glm::dvec3 d(r[3], r[4], r[5]);
                ok = ok && std::abs(glm::length(d) - 1) < 1e-9 && glm::dot(d, sender.normal()) <= 1e-9;
            }
    } catch (const Error&) {
    }
    std::remove(path.c_str());
    return ok;
}

inline bool exerciseDaylightInput(std::string_view input) {
    if (input.empty()) return true;
    std::string rest(input.substr(1));
    try {
        if (input[0] == 'w') {
            std::istringstream in(rest);
            WeatherTape tape(in, "fuzz.wea");
            for (int m : {1, 2}) {
                SkyMatrixOptions o;
                o.subdivisions = m, o.interval = 60;
                SkySteps steps(tape.site(), tape.units(), o);
                std::istringstream again(rest);
                WeatherTape records(again, "fuzz.wea");
                while (std::optional<WeatherRecord> r = records.next())
                    if (std::optional<SkyStep> s = steps.step(*r))
                        for (float v : s->patches)
                            if (!std::isfinite(v)) return false;
            }
        } else if (input[0] == 'r') {
            return exerciseFluxFile(rest);
        } else {
            Matrix m = parseMatrix(rest, "fuzz.mtx");
            for (float v : m.values)
                if (!std::isfinite(v)) return false;
            std::FILE* sink = std::fopen("/dev/null", "w");
            try {
                writeMatrix(sink, multiply(m, transposed(m)), MatrixFormat::Ascii, AsciiLayout::Rmtxop, {"fuzz"});
            } catch (const Error&) {
            }
            std::fclose(sink);
        }
    } catch (const Error&) {
    }
    return true;
}

}  // namespace brume
