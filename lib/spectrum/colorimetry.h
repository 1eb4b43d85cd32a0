// Spectra as observers see them: CIE 1931 XYZ, RGB of given primaries, photopic, scotopic and melanopic
// values. Radiance's normalisation throughout: every sensitivity curve has unit area, so that a flat
// spectrum of 1 gives X = Y = Z = 1, RGB (1, 1, 1) in Radiance's equal-energy-white primaries, and 1 for
// each curve; output options multiply by Radiance's efficacies (179 lm/W photopic, 412 scotopic, 179
// melanopic). With 3 channels (RGB) XYZ comes from the primaries, and scotopic and melanopic values treat
// R, G, B as flat over Radiance's partitions of the range (its WAVELENGTH_SPLITS), as Radiance does.
#pragma once
#include <array>
#include <vector>

#include "spectrum/spectral_sampling.h"
#include "spectrum/spectrum.h"

namespace brume {

using Color3 = std::array<double, 3>;
using Matrix3 = std::array<Color3, 3>;  // rows

struct Chromaticity {
    double x, y;
    bool operator==(const Chromaticity&) const = default;
};
struct Primaries {
    Chromaticity red, green, blue, white;
    bool operator==(const Primaries&) const = default;
};
// The eight numbers Radiance writes for primaries (-pc, PRIMARIES=): xr yr xg yg xb yb xw yw.
inline std::array<double, 8> coordinates(const Primaries& p) {
    return {p.red.x, p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y, p.white.x, p.white.y};
}
inline Primaries primariesOf(const std::array<double, 8>& v) {
    return {{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}
// Radiance's standard primaries (color.h: nominal CRT primaries, equal-energy white).
inline constexpr Primaries kRadiancePrimaries{{0.640, 0.330}, {0.290, 0.600}, {0.150, 0.060}, {1. / 3, 1. / 3}};
// Whether p can be used (Radiance's colorprimsOK): chromaticities inside the unit triangle, a white not
// on a line between primaries, a non-singular matrix.
bool validPrimaries(const Primaries& p);

Color3 operator*(const Matrix3& m, const Color3& c);
Matrix3 operator*(const Matrix3& a, const Matrix3& b);
double determinant(const Matrix3& m);
Matrix3 inverse(const Matrix3& m);
// RGB of primaries p to XYZ, white (1,1,1) ↦ p.white with Y = 1.
Matrix3 rgbToXyz(const Primaries& p);
// XYZ to RGB of primaries p, adapting from equal-energy white to p's white by von Kries in the "sharp"
// sensor space (Süsstrunk, Holm, Finlayson 2001), as Radiance's compxyz2rgbWBmat does.
Matrix3 xyzToRgb(const Primaries& p);

// Per band, the share of each observer curve's area that falls in it.
struct ObserverWeights {
    std::vector<double> x, y, z, scotopic, melanopic;
    // Melanopic to melanopic-equivalent daylight (D65) value: ∫ȳ D65 / ∫s_mel D65, the curves normalised.
    double melanopicToDaylight = 1;
};
// The weights of a sampling (its bands each flat, the curves' areas shared out as Radiance's spec_dot does).
ObserverWeights observerWeightsOf(const SpectralSampling& s);
// The weights of the sampling in effect, read without a lock on every value written: setSpectralSampling
// remakes them (before any thread renders); made on first use otherwise.
const ObserverWeights& observerWeights();
void remakeObserverWeights();

Color3 toXyz(const Spectrum& s);
// RGB in primaries p; out-of-gamut negatives desaturated toward the grey of equal Y (Radiance's clipgamut
// at the lower bound). Radiance's own primaries with 3 channels: the channels as they are.
Color3 toRgb(const Spectrum& s, const Primaries& p = kRadiancePrimaries);
// The same from XYZ.
Color3 xyzToClippedRgb(const Color3& xyz, const Primaries& p = kRadiancePrimaries);
// Radiance's RGB with negatives set to 0 and the rest scaled to keep Y: for light far outside the gamut whose
// grey would be light it does not have (a black body below 2000 K has no blue, below 900 K no green: the
// desaturation above gives a 700 K flame 8 % of its red in blue).
Color3 xyzToRgbWithoutGrey(const Color3& xyz);
double photopic(const Spectrum& s);   // Y (3 channels: Radiance's bright())
double scotopic(const Spectrum& s);   // V'(λ)
double melanopic(const Spectrum& s);  // s_mel(λ) of CIE S 026, normalised to unit area (Radiance's -pM)
// CIE S 026's melanopic equivalent daylight (D65) value: equal to photopic() for a D65 spectrum.
double melanopicDaylight(const Spectrum& s);

// Spectral radiance (W·m⁻²·sr⁻¹·nm⁻¹) per unit of a band's value: a flat spectrum of 1 has Radiance's white
// luminance, 179 cd/m² = 683 lm/W · ∫ L_λ ȳ dλ, so L_λ = 179 / (683 ∫ȳ dλ) ≈ 1/408.
double spectralRadiancePerValue();

}  // namespace brume
