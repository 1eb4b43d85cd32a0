#include "cache/sphere_samples.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;

// A volume record's rays, one uniform in each stratum of cos θ × φ, are together uniform over the sphere:
// draws of a cell chosen uniformly, then of a point uniform in it, follow 1/4π (chi-square,
// sampling/testing.h: 2×10⁵ draws in 20×40 cells about a tilted axis), for few strata and many.
TEST(SphereSamples, StrataTogetherDrawUniformDirections) {
    for (int divisions : {8, 64, 1000}) {
        SphereSamples s(dvec3(0), divisions, 1);
        auto sample = [&](double u, double v) -> std::optional<dvec3> {
            double strata = u * s.count();
            int cell = std::min(int(strata), s.count() - 1);
            return s.direction(cell / s.columns(), cell % s.columns(), strata - cell, v);
        };
        auto density = [](const dvec3&) { return 1 / (4 * std::numbers::pi); };
        SCOPED_TRACE(testing::Message() << s.rows() << "×" << s.columns() << " strata");
        sampling::testing::expectSamplesFollowDensity(
            sample, density, {.draws = 200'000, .rings = 20, .sectors = 40, .axis = glm::normalize(dvec3(1, 2, 0.5))});
    }
}
