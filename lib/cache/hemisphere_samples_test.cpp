#include "cache/hemisphere_samples.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;

// A record's rays, one uniform in each stratum of sin²θ × φ, are together cosine-distributed over the
// hemisphere (Ward & Heckbert's strata are equal shares of cos θ/π): draws of a cell chosen uniformly, then of
// a point uniform in it, follow cos θ/π (chi-square, sampling/testing.h: 2×10⁵ draws in 20×40 cells about the
// normal, the horizon on a cell edge: 10% off over a tenth of the draws fails), for few strata and many.
TEST(HemisphereSamples, StrataTogetherDrawCosineWeightedDirections) {
    const dvec3 normal = glm::normalize(dvec3(0.3, -0.2, 1));
    for (int divisions : {8, 64, 1000}) {
        HemisphereSamples hs(dvec3(0), normal, divisions, 1);
        auto sample = [&](double u, double v) -> std::optional<dvec3> {
            double strata = u * hs.count();
            int cell = std::min(int(strata), hs.count() - 1);
            return hs.direction(cell / hs.columns(), cell % hs.columns(), strata - cell, v);
        };
        auto density = [&](const dvec3& d) { return std::max(0.0, glm::dot(d, normal)) / std::numbers::pi; };
        SCOPED_TRACE(testing::Message() << hs.rows() << "×" << hs.columns() << " strata");
        sampling::testing::expectSamplesFollowDensity(sample, density,
                                                      {.draws = 200'000, .rings = 20, .sectors = 40, .axis = normal});
    }
}
