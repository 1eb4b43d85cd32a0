// What the annual-daylight fuzz target does with an input (see README.md): the first byte picks a weather
// tape ('w': read every record and make its sky, every value finite) or a matrix ('m': read it, transpose it,
// multiply it by the transpose, write it); Error is fine, a value that is not finite a bug.
#pragma once
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <string_view>

#include "matrix/matrix_file.h"
#include "sky/sky_matrix.h"
#include "util/error.h"

namespace brume {

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
