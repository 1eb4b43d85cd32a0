// What rtrace and rpict write for a value of light (Radiance 6.1's -pRGB, -pXYZ, -pc, -pY, -pS, -pM, -pA
// and -co): three colour channels, one weighted sum, or the spectrum itself, with Radiance's scale factors
// (so that -pY with -I gives lux). Brume adds -pMD65: CIE S 026's melanopic equivalent daylight (D65)
// illuminance or luminance.
#pragma once
#include <string>
#include <vector>

#include "spectrum/colorimetry.h"

namespace brume {

struct ColorOutput {
    enum class Kind { Rgb, Xyz, Photopic, Scotopic, Melanopic, MelanopicDaylight, Mean, Spectral };
    Kind kind = Kind::Rgb;
    Primaries primaries = kRadiancePrimaries;  // of Kind::Rgb (-pc)

    // Values per colour: 1, 3, or the bands of the sampling in effect (with 3 bands, spectral is RGB).
    int components() const;
    // Writes components() values for `s`.
    void convert(const Spectrum& s, double* out) const;
    // Header lines Radiance writes for it: WAVELENGTH_SPLITS= for spectra, PRIMARIES= for other primaries.
    std::vector<std::string> headerLines() const;
};

// "PRIMARIES= xr yr xg yg xb yb xw yw", as Radiance writes it.
std::string primariesLine(const Primaries& p);

// Radiance's scale factors: lm/W of equal-energy white (photopic and melanopic) and its scotopic value.
inline constexpr double kWhiteEfficacy = 179, kWhiteScotopic = 412, kWhiteMelanopic = 179;

}  // namespace brume
