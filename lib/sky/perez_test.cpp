#include "sky/perez.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sky/solar_position.h"

using namespace brume;

// Perez et al. (1990): epsilon and delta from irradiances and the irradiances back from them.
TEST(Perez, SkyConditionAndIrradiancesAreInverses) {
    double zenith = 40 * kDegree;
    PerezSkyCondition c = perezSkyCondition(650, 140, zenith, 172);
    EXPECT_NEAR(perezDirectIrradiance(c, zenith, 172), 650, 1e-9);
    EXPECT_NEAR(perezDiffuseIrradiance(c, zenith, 172), 140, 1e-9);
}

// No direct light is an overcast sky, epsilon 1; a clear sky has epsilon above 6 (Perez et al. 1990).
TEST(Perez, ClearnessGoesFromOneOvercastToAboveSixClear) {
    EXPECT_DOUBLE_EQ(perezSkyCondition(0, 200, 0.5, 100).clearness, 1);
    EXPECT_GT(perezSkyCondition(850, 100, 0.5, 100).clearness, 6);
}

// Kasten's (1966) air mass is 1 at the zenith, 2 at 60° and 36.5 at the horizon; the sun is nearest in
// early January ((1/0.9833)² = 1.034) and farthest in early July ((1/1.0167)² = 0.967); Spencer's series
// is good to 0.001.
TEST(Perez, AirMassAndEccentricityHaveTheirKnownValues) {
    EXPECT_NEAR(relativeAirMass(0), 1, 1e-3);
    EXPECT_NEAR(relativeAirMass(60), 2, 0.01);
    EXPECT_NEAR(relativeAirMass(90), 36.5, 0.1);
    EXPECT_NEAR(eccentricityCorrection(3), 1.034, 0.0015);
    EXPECT_NEAR(eccentricityCorrection(185), 0.967, 0.0015);
    EXPECT_NEAR(precipitableWater(10.97353115), 2, 1e-6);
}

// Luminous efficacies in the range Perez et al. (1990) report: diffuse light 100-170 lm/W (bluest for
// clear skies), direct 60-110 lm/W, the direct efficacy falling as the sun gets low.
TEST(Perez, EfficaciesAreThoseOfDaylight) {
    PerezSkyCondition clear{6.5, 0.12}, overcast{1.02, 0.25};
    for (double zenith : {20.0, 50.0, 75.0}) {
        for (PerezSkyCondition c : {clear, overcast}) {
            EXPECT_GT(diffuseEfficacy(c, zenith * kDegree, 2), 100);
            EXPECT_LT(diffuseEfficacy(c, zenith * kDegree, 2), 170);
        }
        EXPECT_GT(directEfficacy(clear, zenith * kDegree, 2), 60);
        EXPECT_LT(directEfficacy(clear, zenith * kDegree, 2), 110);
    }
    EXPECT_GT(directEfficacy(clear, 20 * kDegree, 2), directEfficacy(clear, 75 * kDegree, 2));
}

// A clear sky is brightest around the sun and darkest about 90° from it; an overcast one is brighter at
// the zenith than at the horizon (Perez, Seals & Michalsky 1993, fig. 2).
TEST(Perez, ClearSkyPeaksAtTheSunAndOvercastAtTheZenith) {
    double sunZenith = 40 * kDegree;
    PerezCoefficients clear = perezCoefficients(sunZenith, {6.5, 0.12});
    EXPECT_GT(perezRelativeLuminance(clear, sunZenith, 0.05), 5 * perezRelativeLuminance(clear, 50 * kDegree, 90 * kDegree));
    PerezCoefficients overcast = perezCoefficients(sunZenith, {1, 0.2});
    EXPECT_GT(perezRelativeLuminance(overcast, 0, sunZenith), 1.5 * perezRelativeLuminance(overcast, 85 * kDegree, 100 * kDegree));
}
