// Observer quantities against values worked out by hand from the CIE tables, and Radiance's conventions.
#include "spectrum/colorimetry.h"

#include <gtest/gtest.h>

#include "spectral_sampling_scope.h"
#include "spectrum/cie_tables.h"
#include "spectrum/color_output.h"

using namespace brume;

namespace {

// A spectrum's band averages of a tabulated function.
Spectrum bandsOf(const TabulatedSpectrum& f) {
    const SpectralSampling& s = spectralSampling();
    Spectrum out(0.f, s.channels);
    for (int i = 0; i < s.channels; ++i) {
        auto b = s.band(i);
        out[i] = float(f.integral(b[1], b[0]) / (b[0] - b[1]));
    }
    return out;
}

double chromaticityX(const Color3& c) { return c[0] / (c[0] + c[1] + c[2]); }
double chromaticityY(const Color3& c) { return c[1] / (c[0] + c[1] + c[2]); }

}  // namespace

TEST(Colorimetry, RadiancePrimariesMapWhiteToEqualEnergy) {
    Color3 xyz = rgbToXyz(kRadiancePrimaries) * Color3{1, 1, 1};
    for (double v : xyz) EXPECT_NEAR(v, 1, 1e-12);
    // Radiance's luminance weights are the matrix's Y row (color.h's comment: .265074126, .670114631,
    // .064811243; its formula, as here, gives them to 4e-5).
    Matrix3 m = rgbToXyz(kRadiancePrimaries);
    EXPECT_NEAR(m[1][0], .265074126, 4e-5);
    EXPECT_NEAR(m[1][1], .670114631, 4e-5);
    EXPECT_NEAR(m[1][2], .064811243, 4e-5);
    Color3 back = xyzToRgb(kRadiancePrimaries) * xyz;
    for (double v : back) EXPECT_NEAR(v, 1, 1e-12);
}

TEST(Colorimetry, OtherWhitesAreAdaptedTo) {
    // Equal-energy white shown in D65 primaries is their white (1,1,1): von Kries adaptation.
    Primaries srgb{{.64, .33}, {.30, .60}, {.15, .06}, {.3127, .3290}};
    Color3 rgb = xyzToRgb(srgb) * Color3{1, 1, 1};
    for (double v : rgb) EXPECT_NEAR(v, 1, 1e-9);
    EXPECT_TRUE(validPrimaries(srgb));
    EXPECT_FALSE(validPrimaries({{.64, .33}, {.64, .33}, {.15, .06}, {.31, .33}}));
    EXPECT_FALSE(validPrimaries({{.64, .33}, {.30, .60}, {.15, .06}, {.9, .05}}));
}

TEST(Colorimetry, FlatSpectrumIsWhiteInEveryQuantity) {
    SpectralSamplingScope bands(41, 360, 830);
    Spectrum flat(1.f);
    Color3 xyz = toXyz(flat);
    for (double v : xyz) EXPECT_NEAR(v, 1, 1e-6);
    EXPECT_NEAR(photopic(flat), 1, 1e-6);
    EXPECT_NEAR(scotopic(flat), 1, 1e-6);
    EXPECT_NEAR(melanopic(flat), 1, 1e-6);
    Color3 rgb = toRgb(flat);
    for (double v : rgb) EXPECT_NEAR(v, 1, 1e-6);
}

// CIE 15: illuminant A at (0.44757, 0.40745), D65 at (0.31272, 0.32903). Bands of 5 nm over 380–780 nm
// hold them within 0.001 (the tolerance; what is left is the bands' width and range).
TEST(Colorimetry, StandardIlluminantChromaticities) {
    SpectralSamplingScope bands(80);
    Color3 a = toXyz(bandsOf(illuminantA()));
    EXPECT_NEAR(chromaticityX(a), 0.44757, 0.001);
    EXPECT_NEAR(chromaticityY(a), 0.40745, 0.001);
    Color3 d = toXyz(bandsOf(illuminantD65()));
    EXPECT_NEAR(chromaticityX(d), 0.31272, 0.001);
    EXPECT_NEAR(chromaticityY(d), 0.32903, 0.001);
}

// CIE S 026: D65 has melanopic EDI equal to its illuminance, by definition.
TEST(Colorimetry, MelanopicDaylightOfD65IsItsPhotopicValue) {
    SpectralSamplingScope bands(81);
    Spectrum d65 = bandsOf(illuminantD65()) * 0.01f;
    EXPECT_NEAR(melanopicDaylight(d65) / photopic(d65), 1, 2e-3);
    Spectrum a = bandsOf(illuminantA()) * 0.01f;
    EXPECT_LT(melanopicDaylight(a), 0.6 * photopic(a));  // warm light: far less melanopic (A: ≈ 0.45)
}

TEST(ColorOutput, RadianceScaleFactors) {
    SpectralSamplingScope bands(41);
    Spectrum flat(1.f);
    double v[96];
    ColorOutput o;
    o.kind = ColorOutput::Kind::Photopic;
    o.convert(flat, v);
    EXPECT_NEAR(v[0], 179 * photopic(flat), 1e-9);
    o.kind = ColorOutput::Kind::Scotopic;
    o.convert(flat, v);
    EXPECT_NEAR(v[0], 412 * scotopic(flat), 1e-9);
    o.kind = ColorOutput::Kind::Xyz;
    o.convert(flat, v);
    EXPECT_NEAR(v[1], 179 * photopic(flat), 1e-9);
    o.kind = ColorOutput::Kind::Spectral;
    EXPECT_EQ(o.components(), 41);
    ASSERT_EQ(o.headerLines().size(), 1u);
    EXPECT_EQ(o.headerLines()[0], "WAVELENGTH_SPLITS= 780 588 480 380");
}

TEST(ColorOutput, RgbPhotopicIsRadiancesBright) {
    Spectrum c(.5f, .25f, .125f);
    EXPECT_NEAR(photopic(c), .265 * .5 + .670 * .25 + .065 * .125, 2e-4);
}
