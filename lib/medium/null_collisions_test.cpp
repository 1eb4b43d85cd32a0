// Null-collision tracking against Beer–Lambert: in a medium of known extinction delta tracking's means are
// exp(−τ) and 1 − exp(−τ), band by band, whatever the majorant.
#include "medium/null_collisions.h"

#include <gtest/gtest.h>

#include <vector>

using namespace brume;

// Delta tracking with spectral weights: per band, the weighted chance of colliding before the end is
// 1 − exp(−τ_λ) and of getting through exp(−τ_λ), though the bands' extinctions differ fourfold (1%, the
// estimates' standard error below 0.3%).
TEST(NullCollisions, SpectralDeltaTrackingIsUnbiasedInEveryBand) {
    double length = 1.0;
    Spectrum sigma(0.5f, 1.f, 2.f);
    std::vector<MajorantSegment> segments{{0, length, 2.5}};
    Random random(7, 2);
    Spectrum collided(0.f, 3), through(0.f, 3);
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        Spectrum weight(1.f, 3);
        std::optional<double> t = deltaTracking(segments, [&](double) { return sigma; }, weight, random);
        if (t) {
            ASSERT_GE(*t, 0);
            ASSERT_LT(*t, length);
            collided += weight;
        } else {
            through += weight;
        }
    }
    for (int c = 0; c < 3; ++c) {
        double escape = std::exp(-sigma[c] * length);
        EXPECT_NEAR(through[c] / n, escape, 0.01 * escape) << "band " << c;
        EXPECT_NEAR(collided[c] / n, 1 - escape, 0.01 * (1 - escape)) << "band " << c;
    }
}

// Empty stretches (majorant 0) cost nothing and change nothing.
TEST(NullCollisions, EmptySegmentsAreSkipped) {
    std::vector<MajorantSegment> segments{{0, 1e9, 0}};
    Random random(1, 1);
    Spectrum weight(1.f, 3);
    EXPECT_FALSE(deltaTracking(segments, [](double) -> Spectrum { throw 0; }, weight, random));
    EXPECT_EQ(weight[2], 1.f);
}
