#include "matrix/symbolic_components.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <map>
#include <optional>

#include "spectrum/colorimetry.h"
#include "util/error.h"

namespace brume {

namespace {

// Radiance 6.1's rmtxop's weights for its RGB primaries (read off `rmtxop -fd -c x` and so on applied to the
// unit colours).
std::vector<double> rgbWeights(char lower) {
    static const std::map<char, std::array<double, 3>> kUnscaled = {
        {'x', {0.5141445994377136, 0.3238844871520996, 0.16197089850902557}},
        {'y', {0.26510581374168396, 0.6701058149337769, 0.06478835642337799}},
        {'z', {0.0241005290299654, 0.12285273522138596, 0.853046715259552}},
        {'s', {0.011291676200926304, 0.7089188694953918, 0.27978941798210144}},
        {'m', {0.0018310826271772385, 0.6002899408340454, 0.3978790044784546}},
        {'r', {1, 0, 0}}, {'g', {0, 1, 0}}, {'b', {0, 0, 1}}, {'a', {1.0 / 3, 1.0 / 3, 1.0 / 3}}};
    auto it = kUnscaled.find(lower);
    return it == kUnscaled.end() ? std::vector<double>{} : std::vector<double>(it->second.begin(), it->second.end());
}

std::vector<double> spectralWeights(char lower, const ObserverWeights& w, int comps) {
    switch (lower) {
        case 'x': return w.x;
        case 'y': return w.y;
        case 'z': return w.z;
        case 's': return w.scotopic;
        case 'm': return w.melanopic;
        case 'a': return std::vector<double>(size_t(comps), 1.0 / comps);
        case 'r': case 'g': case 'b': {
            const Matrix3 toRgb = xyzToRgb(kRadiancePrimaries);
            const size_t row = lower == 'r' ? 0 : lower == 'g' ? 1 : 2;
            std::vector<double> channel;
            for (size_t i = 0; i < size_t(comps); ++i) channel.push_back((toRgb * Color3{w.x[i], w.y[i], w.z[i]})[row]);
            return channel;
        }
        default: return {};
    }
}

}  // namespace

SpectralSampling bandsOf(const Matrix& m) {
    SpectralSampling s;
    s.channels = m.comps;
    for (const std::string& line : m.info) {
        double split[4];
        if (std::sscanf(line.c_str(), "WAVELENGTH_SPLITS= %lf %lf %lf %lf", &split[0], &split[1], &split[2], &split[3]) != 4)
            continue;
        s.longest = std::max(split[0], split[3]), s.shortest = std::min(split[0], split[3]);
        if (!validSpectralRange(s.shortest, s.longest))
            throw Error("'" + line + "': the spectral range must span 50 nm or more within 200 to 2000 nm");
    }
    return s;
}

std::vector<double> symbolWeights(const std::string& symbols, const Matrix& m) {
    if (m.comps < 3) throw Error("symbolic components (-c " + symbols + ") need 3 components or more, not " + std::to_string(m.comps));
    std::optional<ObserverWeights> bands;
    if (m.comps > 3) bands = observerWeightsOf(bandsOf(m));
    std::vector<double> w;
    for (char c : symbols) {
        char lower = char(std::tolower(static_cast<unsigned char>(c)));
        std::vector<double> row = bands ? spectralWeights(lower, *bands, m.comps) : rgbWeights(lower);
        if (row.empty()) throw Error(std::string("symbolic component '") + c + "' is not one of R G B X Y Z S M A");
        bool efficacy = c != lower && std::string("xyzsm").find(lower) != std::string::npos;
        double scale = !efficacy ? 1 : lower == 's' ? 412 : 179;
        for (double v : row) w.push_back(float(float(v) * scale));  // Radiance's single precision
    }
    return w;
}

}  // namespace brume
