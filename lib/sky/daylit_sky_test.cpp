#include "sky/daylit_sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "sky/cie_sky.h"
#include "sky/hemisphere_quadrature_test.h"
#include "util/error.h"

using namespace brume;

namespace {

struct Case {
    DaylitInput input;
    double first, second;
    double altitude;  // degrees
};

const Case kSkies[] = {
    {DaylitInput::NormalIrradiance, 840, 135, 60},  // clear
    {DaylitInput::NormalIrradiance, 720, 280, 60},  // turbid
    {DaylitInput::NormalIrradiance, 300, 200, 20},  // intermediate, low sun
    {DaylitInput::NormalIrradiance, 0, 150, 35},    // overcast
    {DaylitInput::PerezParameters, 1, 0.35, 40},    // bright overcast
    {DaylitInput::NormalIrradiance, 100, 60, 6},    // sun near the horizon
};

DaylitRequest requestFor(const Case& c, DaylitOutput output = DaylitOutput::VisibleRadiance) {
    DaylitRequest r;
    r.input = c.input, r.first = c.first, r.second = c.second, r.output = output;
    r.dayNumber = 172;
    return r;
}

// The sky radiance toward d, as perezlum.cal gives it above the horizon.
double skyRadiance(const DaylitSky& sky, const SunAngles& sun, const glm::dvec3& d) {
    glm::dvec3 s = sunDirection(sun);
    double gamma = std::acos(std::clamp(glm::dot(s, d), -1.0, 1.0));
    return sky.diffuseNormalisation * perezRelativeLuminance(sky.coefficients, std::acos(d.z), gamma);
}

class QuietWarnings : public ::testing::Test {
protected:
    void SetUp() override { setWarningsEnabled(false); }
    void TearDown() override { setWarningsEnabled(true); }
};

}  // namespace

using DaylitSkyTest = QuietWarnings;

// gendaylit scales the sky so that its 145-point sum of radiance × cos θ × 2π/145 gives back the diffuse
// horizontal irradiance exactly (-O 1, W/m²). That sum is a coarse quadrature, kept as Radiance has it:
// the true integral over the hemisphere differs from the input by less than 5% for 607 of 608 -W skies
// (sun 5° to 85°, direct 0-900, diffuse 20-450 W/m²), at worst 7.8% (a very dark sky, delta 0.02).
TEST_F(DaylitSkyTest, DiffuseSkyIntegratesToTheInputDiffuseIrradiance) {
    for (const Case& c : kSkies) {
        DaylitRequest r = requestFor(c, DaylitOutput::SolarRadiance);
        SunAngles sun{c.altitude * kDegree, 0.3};
        DaylitSky sky = makeDaylitSky(r, sun);
        ASSERT_FALSE(sky.error) << c.first << " " << c.second;
        double zenith = kPi / 2 - sun.altitude;
        double input = r.input == DaylitInput::PerezParameters ? perezDiffuseIrradiance(sky.condition, zenith, r.dayNumber) : c.second;
        EXPECT_NEAR(sky.diffuseNormalisation * perezHorizontalSum(sky.coefficients, zenith), input, 1e-9 * input);
        double integral = horizontalIntegral([&](const glm::dvec3& d) { return skyRadiance(sky, sun, d); });
        EXPECT_NEAR(integral / input, 1, 0.05) << c.first << " " << c.second << " at " << c.altitude << "°";
    }
}

// In the default output (-O 0) the sky is in Radiance's visible watts: illuminance over 179 lm/W; the
// sun's radiance over its 0.533° disc gives the direct normal illuminance.
TEST_F(DaylitSkyTest, VisibleRadianceIsIlluminanceOverWhiteEfficacy) {
    Case clear = kSkies[0];
    SunAngles sun{clear.altitude * kDegree, 0};
    DaylitSky watts = makeDaylitSky(requestFor(clear, DaylitOutput::VisibleRadiance), sun);
    DaylitSky lumens = makeDaylitSky(requestFor(clear, DaylitOutput::Luminance), sun);
    EXPECT_NEAR(watts.diffuseNormalisation * kWhiteEfficacy, lumens.diffuseNormalisation, 1e-9 * lumens.diffuseNormalisation);
    EXPECT_NEAR(watts.solarRadiance * kWhiteEfficacy, lumens.solarRadiance, 1e-9 * lumens.solarRadiance);
    double zenith = kPi / 2 - sun.altitude, water = precipitableWater(10.97353115);
    double directIlluminance = clear.first * directEfficacy(lumens.condition, zenith, water);
    EXPECT_NEAR(lumens.solarRadiance * daylitSunSolidAngle(), directIlluminance, 1e-9 * directIlluminance);
}

// -L takes illuminances and finds the irradiances whose Perez efficacies give them: the illuminances of
// a -W sky, given to -L, give back the same sky (away from the clearness bins' edges, where the
// efficacies jump and the iteration may settle in the neighbouring bin).
TEST_F(DaylitSkyTest, IlluminanceInputRecoversTheIrradianceSky) {
    for (const Case& c : {kSkies[0], kSkies[1]}) {
        SunAngles sun{c.altitude * kDegree, 0};
        DaylitSky fromIrradiance = makeDaylitSky(requestFor(c, DaylitOutput::Luminance), sun);
        double zenith = kPi / 2 - sun.altitude, water = precipitableWater(10.97353115);
        Case asIlluminance{DaylitInput::NormalIlluminance, c.first * directEfficacy(fromIrradiance.condition, zenith, water),
                           c.second * diffuseEfficacy(fromIrradiance.condition, zenith, water), c.altitude};
        DaylitSky fromIlluminance = makeDaylitSky(requestFor(asIlluminance, DaylitOutput::Luminance), sun);
        EXPECT_NEAR(fromIlluminance.condition.clearness, fromIrradiance.condition.clearness, 0.01 * fromIrradiance.condition.clearness);
        EXPECT_NEAR(fromIlluminance.diffuseNormalisation, fromIrradiance.diffuseNormalisation, 0.01 * fromIrradiance.diffuseNormalisation);
    }
}

// gendaylit's "error sky": no light with the sun up, or more direct light than the solar constant.
TEST_F(DaylitSkyTest, ImpossibleInputsGiveTheErrorSky) {
    SunAngles sun{30 * kDegree, 0};
    EXPECT_TRUE(makeDaylitSky(requestFor({DaylitInput::NormalIrradiance, 0, 0, 30}), sun).error);
    EXPECT_TRUE(makeDaylitSky(requestFor({DaylitInput::NormalIrradiance, 1400, 100, 30}), sun).error);
    EXPECT_FALSE(makeDaylitSky(requestFor({DaylitInput::NormalIrradiance, 800, 100, 30}), sun).error);
}

// Erbs et al. (1982): the diffuse share of a global irradiance, and -E then behaves as -G with the split.
TEST_F(DaylitSkyTest, GlobalIrradianceIsSplitIntoDirectAndDiffuse) {
    SunAngles sun{50 * kDegree, 0};
    DaylitRequest global = requestFor({DaylitInput::GlobalIrradiance, 700, 0, 50}, DaylitOutput::SolarRadiance);
    DaylitSky sky = makeDaylitSky(global, sun);
    ASSERT_EQ(sky.comments.size(), 2u);
    double s0, kt, directHorizontal, diffuse;
    ASSERT_EQ(std::sscanf(sky.comments[0].c_str(), "# erbs_s0, erbs_kt, irr_dir_h, irr_diff: %lf %lf %lf %lf", &s0, &kt,
                          &directHorizontal, &diffuse), 4);
    EXPECT_NEAR(directHorizontal + diffuse, 700, 0.01);
    EXPECT_NEAR(kt, 700 / s0, 1e-3);
    DaylitSky split = makeDaylitSky(requestFor({DaylitInput::HorizontalIrradiance, directHorizontal, diffuse, 50},
                                               DaylitOutput::SolarRadiance), sun);
    EXPECT_NEAR(split.diffuseNormalisation, sky.diffuseNormalisation, 1e-4 * sky.diffuseNormalisation);
}
