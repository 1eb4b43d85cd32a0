#include "sky/sky_patches.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "sky/solar_position.h"

namespace brume {
namespace {

// Tregenza's 145 patches and Reinhart's subdivisions: the sky's patches cover the hemisphere (2π sr), each
// patch's centre is a unit vector above the horizon, and rows run from the horizon up.
TEST(SkyPatches, CoverTheHemisphere) {
    for (int m : {1, 2, 4}) {
        SkyPatches p(m);
        EXPECT_EQ(p.size(), 144 * m * m + 2);
        double sky = 0;
        for (int i = 1; i < p.size(); ++i) {
            sky += p[i].solidAngle;
            EXPECT_GT(p[i].altitude, 0);
            EXPECT_NEAR(glm::length(p.direction(i)), 1, 1e-12);
            if (i > 1) {
                EXPECT_GE(p[i].altitude, p[i - 1].altitude);
            }
        }
        EXPECT_NEAR(sky, 2 * kPi, 1e-5) << m;
        EXPECT_FLOAT_EQ(p[0].solidAngle, float(2 * kPi));
        EXPECT_FLOAT_EQ(p[p.size() - 1].altitude, float(kPi / 2));
    }
    SkyPatches t(1);
    EXPECT_NEAR(t.direction(1).y, std::cos(6 * kDegree), 1e-6);  // the first patch looks north, 6° up
    EXPECT_NEAR(t.direction(31).z, std::sin(18 * kDegree), 1e-6);  // the second row, 18° up
}

// Radiance's table: exact at multiples of π/2048, within half a step's slope between them.
TEST(SkyPatches, TabulatedSineIsTheTable) {
    for (int k = -4096; k <= 4096; k += 37) EXPECT_NEAR(tabulatedSine(k * kPi / 2048), std::sin(k * kPi / 2048), 1e-15);
    for (double x = -3; x < 3; x += 0.0123) EXPECT_NEAR(tabulatedSine(x), std::sin(x), kPi / 4096 + 1e-12);
}

}  // namespace
}  // namespace brume
