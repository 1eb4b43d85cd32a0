// Rendering in wavelength bands: physical answers that hold band by band, and RGB scenes that render the
// same in RGB and in bands.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene_text.h"
#include "spectral_sampling_scope.h"
#include "spectrum/cie_tables.h"
#include "spectrum/colorimetry.h"

using namespace brume;
using namespace brume::test;
using std::numbers::pi;

namespace {

// A `spectrum` primitive of CIE illuminant A from its defining formula (CIE 15), 380–780 nm every 5 nm,
// normalised to 1 at 560 nm.
std::string illuminantASpectrum(const std::string& name) {
    std::ostringstream s;
    s << "void spectrum " << name << " 0 0 83 380 780";
    for (int nm = 380; nm <= 780; nm += 5) {
        double c2 = 1.435e7, t = 2848;
        s << " " << std::pow(560.0 / nm, 5) * std::expm1(c2 / (t * 560)) / std::expm1(c2 / (t * nm));
    }
    return s.str() + "\n";
}

// A ray's value from inside a scene.
Spectrum radianceAlong(const std::string& scene, const dvec3& org, const dvec3& dir, const RenderSettings& s) {
    TestScene t(scene);
    Integrator integrator(t.render, s);
    return test::trace(integrator, org, dir, 0).value;
}

}  // namespace

// White furnace, band by band: a grey sphere (ρ = 0.5) inside a closed glowing shell of radiance L(λ) (an
// illuminant-A spectrum) reflects exactly ρ L(λ) (a convex body sees the shell alone); cosine-weighted
// samples of a uniform field have no variance, so only float rounding is left (tolerance 1e-4).
TEST(Spectral, WhiteFurnaceHoldsInEveryBand) {
    SpectralSamplingScope bands(41);
    std::string scene = illuminantASpectrum("warm") +
                        "warm glow shell 0 0 4 1 1 1 0\n"
                        "shell bubble furnace 0 0 4 0 0 0 10\n"
                        "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                        "grey sphere ball 0 0 4 0 0 0 1\n";
    RenderSettings s = fixedSeed();
    s.ambientBounces = 1, s.ambientAccuracy = 0, s.ambientDivisions = 64;
    Spectrum shell = radianceAlong(scene, dvec3(0, 0, -5), dvec3(0, 0, -1), s);
    Spectrum ball = radianceAlong(scene, dvec3(0, 0, -5), dvec3(0, 0, 1), s);
    ASSERT_EQ(ball.size(), 41);
    EXPECT_GT(shell[0], 2 * shell[40]);  // illuminant A: far more red than blue
    for (int i = 0; i < 41; ++i) EXPECT_NEAR(ball[i], 0.5 * shell[i], 1e-4 * shell[i]) << "band " << i;
}

// An integrating sphere (ρ = 0.5, a central lamp) in 41 bands: E = E₀ (1 − ρ⁶)/(1 − ρ) after five bounces in
// each band, as in RGB (analytic_test.cpp), tolerance 1.5% (6 sensors × 1024 paths, ~0.4% noise per band);
// through the irradiance cache (-aa .1) the all-bounce E₀/(1 − ρ), the cache tests' 1% on the mean.
TEST(Spectral, IntegratingSphereIn41Bands) {
    SpectralSamplingScope bands(41);
    double rho = 0.5, lampRadius = 0.02, lampRadiance = 1000;
    std::ostringstream scene;
    scene << "void plastic wall 0 0 5 .5 .5 .5 0 0\nwall bubble inside 0 0 4 0 0 0 1\n"
          << "void light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4 0 0 0 " << lampRadius << "\n";
    TestScene t(scene.str());
    double direct = 4 * pi * lampRadius * lampRadius * pi * lampRadiance / (4 * pi);
    auto mean = [&](const RenderSettings& s) {
        Sequence sequence(t.scene, t.render, s);
        const dvec3 dirs[] = {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-0.6, 0.8, 0}, {0, -0.6, 0.8}, {0.48, 0.6, -0.64}};
        std::vector<Spectrum> values(6);
        sequence.run(6, 0, [&](size_t i, WorkItem& item) {
            values[i] = sequence.integrator().irradiance({dirs[i] * (1 - 1e-4), -dirs[i], i}, item).value;
        });
        Spectrum sum(0.f);
        for (const Spectrum& v : values) sum += v * (1.f / 6);
        return sum;
    };
    RenderSettings s = fixedSeed();
    s.ambientBounces = 5, s.ambientAccuracy = 0, s.ambientDivisions = 1024;
    Spectrum paths = mean(s);
    double expected = direct * (1 - std::pow(rho, 6)) / (1 - rho);
    for (int b = 0; b < 41; ++b) EXPECT_NEAR(paths[b], expected, 0.015 * expected) << "band " << b;
    s.ambientAccuracy = 0.1;
    Spectrum cached = mean(s);
    EXPECT_NEAR(cached.average(), direct / (1 - rho), 0.01 * direct / (1 - rho));
    for (int b = 0; b < 41; ++b) EXPECT_NEAR(cached[b], cached[0], 1e-5 * cached[0]);  // a grey's bands stay equal
}

// A grey room lit by a white lamp is the same in RGB and in 41 bands: flat spectra, the same paths (the
// photopic weights of brightness sum to 1), so the same numbers up to float rounding. Tolerance 1% (the
// issue's); measured ~1e-6.
TEST(Spectral, GreySceneIsTheSameInRgbAndBands) {
    std::string scene =
        "void plastic floor 0 0 5 .3 .3 .3 0 0\nvoid plastic wall 0 0 5 .7 .7 .7 0 0\n"
        "void metal steel 0 0 5 .6 .6 .6 .9 .05\nvoid light lamp 0 0 3 50 50 50\n"
        "floor polygon f 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0\nwall polygon c 0 0 12 0 0 2.5 0 3 2.5 4 3 2.5 4 0 2.5\n"
        "wall polygon w1 0 0 12 0 0 0 0 0 2.5 4 0 2.5 4 0 0\nwall polygon w2 0 0 12 0 3 0 4 3 0 4 3 2.5 0 3 2.5\n"
        "wall polygon w3 0 0 12 0 0 0 0 3 0 0 3 2.5 0 0 2.5\nsteel polygon w4 0 0 12 4 0 0 4 0 2.5 4 3 2.5 4 3 0\n"
        "lamp sphere bulb 0 0 4 2 1.5 2.2 .1\n";
    RenderSettings s = fixedSeed();
    s.ambientBounces = 3, s.ambientAccuracy = 0, s.ambientDivisions = 256;
    auto illuminances = [&] {
        TestScene t(scene);
        Integrator integrator(t.render, s);
        std::vector<double> lux;
        for (double x : {0.5, 2.0, 3.5})
            for (double y : {0.5, 2.5}) lux.push_back(179 * photopic(test::irradiance(integrator, {x, y, 0.8}, {0, 0, 1}, 7).value));
        return lux;
    };
    std::vector<double> rgb = illuminances();
    SpectralSamplingScope bands(41);
    std::vector<double> spectral = illuminances();
    for (size_t i = 0; i < rgb.size(); ++i) EXPECT_NEAR(spectral[i], rgb[i], 0.01 * rgb[i]) << "sensor " << i;
}

// CIE 15: illuminant A's chromaticity is (0.44757, 0.40745). A glow of its spectrum seen in 41 bands gives it
// within 0.001 (the tolerance: the 9.8 nm bands' average of light and observer).
TEST(Spectral, IlluminantASourceHasItsChromaticity) {
    SpectralSamplingScope bands(41);
    std::string scene = illuminantASpectrum("a") + "a glow tungsten 0 0 4 1 1 1 0\ntungsten sphere s 0 0 4 0 0 0 1\n";
    Color3 xyz = toXyz(radianceAlong(scene, dvec3(0, 0, -5), dvec3(0, 0, 1), fixedSeed()));
    double sum = xyz[0] + xyz[1] + xyz[2];
    EXPECT_NEAR(xyz[0] / sum, 0.44757, 0.001);
    EXPECT_NEAR(xyz[1] / sum, 0.40745, 0.001);
}

// A glow whose spectrum is 1 about 500–510 nm (one band of -cs 40) has photopic radiance ∫ ȳ / ∫ȳ over
// what it covers, melanopic ∫ s_mel / ∫ s_mel: worked here from the CIE tables.
TEST(Spectral, PhotopicAndMelanopicOfANarrowBandByHand) {
    SpectralSamplingScope bands(40);  // 10 nm bands, 780 … 380
    std::string scene = "void spectrum cyan 0 0 5 500 510 1 1 1\ncyan glow g 0 0 4 1 1 1 0\ng sphere s 0 0 4 0 0 0 1\n";
    Spectrum v = radianceAlong(scene, dvec3(0, 0, -5), dvec3(0, 0, 1), fixedSeed());
    const TabulatedSpectrum& y = cieY();
    const TabulatedSpectrum& mel = melanopicEfficiency();
    // The three samples stand for 5 nm bins centred on them (Radiance's half step beyond either end:
    // 497.5–512.5 nm), averaged into bands: 500–510 whole, a quarter of 490–500 and of 510–520.
    double photopicByHand = (y.integral(500, 510) + 0.25 * y.integral(490, 500) + 0.25 * y.integral(510, 520)) /
                            y.integral(y.first, y.last());
    double melanopicByHand = (mel.integral(500, 510) + 0.25 * mel.integral(490, 500) + 0.25 * mel.integral(510, 520)) /
                             mel.integral(mel.first, mel.last());
    EXPECT_NEAR(photopic(v), photopicByHand, 1e-6);
    EXPECT_NEAR(melanopic(v), melanopicByHand, 1e-6);
    EXPECT_NEAR(v[27], 1, 1e-6);  // band 27: 510–500 nm
    EXPECT_NEAR(v[26], 0.25, 1e-6);
}

// Bad spectral patterns are refused with the file, line and what is wrong.
TEST(Spectral, BadSpectralPatternsAreRefused) {
    SpectralSamplingScope bands(41);
    auto error = [](const std::string& pattern) {
        return renderSceneError(pattern + "p plastic m 0 0 5 .5 .5 .5 0 0\nm sphere s 0 0 4 0 0 0 1\n");
    };
    EXPECT_NE(error("void spectrum p 0 0 4 400 700 1 1\n").find("test.rad:1: bad arguments for spectrum \"p\""),
              std::string::npos);
    EXPECT_NE(error("void spectrum p 0 0 5 500 500 1 1 1\n").find("must differ"), std::string::npos);
    EXPECT_NE(error("void specfunc p 2 f . 0 2 900 1000\n").find("outside the spectral range"), std::string::npos);
    EXPECT_NE(error("void specfile p 1 no_such_file.dat 0 0\n").find("no_such_file.dat"), std::string::npos);
    EXPECT_NE(error("void specpict p 5 f no_such.hsr . u v 0 0\n").find("cannot find hyperspectral picture"),
              std::string::npos);
}
