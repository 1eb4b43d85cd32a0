#include "spectrum/color_output.h"

#include <cstdio>

namespace brume {

int ColorOutput::components() const {
    switch (kind) {
        case Kind::Rgb:
        case Kind::Xyz: return 3;
        case Kind::Spectral: return spectralSampling().channels;
        default: return 1;
    }
}

void ColorOutput::convert(const Spectrum& s, double* out) const {
    switch (kind) {
        case Kind::Rgb: {
            Color3 c = toRgb(s, primaries);
            std::copy(c.begin(), c.end(), out);
            return;
        }
        case Kind::Xyz: {
            Color3 c = toXyz(s);
            for (int i = 0; i < 3; ++i) out[i] = kWhiteEfficacy * c[size_t(i)];
            return;
        }
        case Kind::Spectral:
            // Radiance keeps colours in single precision; these are exactly those values.
            for (int i = 0; i < s.size(); ++i) out[i] = s[i];
            return;
        case Kind::Photopic: *out = kWhiteEfficacy * photopic(s); return;
        case Kind::Scotopic: *out = kWhiteScotopic * scotopic(s); return;
        case Kind::Melanopic: *out = kWhiteMelanopic * melanopic(s); return;
        case Kind::MelanopicDaylight: *out = kWhiteEfficacy * melanopicDaylight(s); return;
        case Kind::Mean: *out = s.average(); return;
    }
}

std::vector<std::string> ColorOutput::headerLines() const {
    if (kind == Kind::Spectral && !spectralSampling().isRgb()) {
        char line[80];
        auto w = spectralSampling().splits();
        std::snprintf(line, sizeof line, "WAVELENGTH_SPLITS= %g %g %g %g", w[0], w[1], w[2], w[3]);
        return {line};
    }
    if (kind == Kind::Rgb && primaries != kRadiancePrimaries) return {primariesLine(primaries)};
    return {};
}

std::string primariesLine(const Primaries& p) {
    std::array<double, 8> v = coordinates(p);
    char line[160];
    std::snprintf(line, sizeof line, "PRIMARIES= %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f", v[0], v[1], v[2], v[3], v[4],
                  v[5], v[6], v[7]);
    return line;
}

}  // namespace brume
