// Null-collision tracking against Beer–Lambert: in a medium of known extinction the estimators' means are
// exp(−τ) and 1 − exp(−τ), band by band, whatever the majorant.
#include "medium/null_collisions.h"

#include <gtest/gtest.h>

#include <vector>

using namespace brume;

namespace {

// Mean and standard error of `n` estimates.
template <class F>
std::pair<Spectrum, Spectrum> meanOf(int n, int channels, F estimate) {
    Spectrum sum(0.f, channels), squares(0.f, channels);
    for (int i = 0; i < n; ++i) {
        Spectrum e = estimate(i);
        sum += e;
        squares += e * e;
    }
    Spectrum mean = sum * (1.f / n), error(0.f, channels);
    for (int c = 0; c < channels; ++c) error[c] = std::sqrt(std::max(0.f, squares[c] / n - mean[c] * mean[c]) / n);
    return {mean, error};
}

}  // namespace

// Beer–Lambert at optical depths 0.01, 1 and 5 (the issue's), three bands of different extinction under one
// majorant twice the largest: the mean of ratio tracking within 1% (its standard error below 0.35%, from a
// million estimates).
TEST(NullCollisions, RatioTrackingGivesBeerLambert) {
    for (double tau : {0.01, 1.0, 5.0}) {
        double length = 2.0;
        Spectrum sigma(float(0.5 * tau / length), float(tau / length), float(0.8 * tau / length));
        std::vector<MajorantSegment> segments{{0, 0.7, 2 * tau / length}, {0.7, length, 2 * tau / length}};
        Random random(5, uint64_t(tau * 100));
        auto [mean, error] = meanOf(1000000, 3, [&](int) {
            return ratioTracking(segments, [&](double) { return sigma; }, random);
        });
        for (int c = 0; c < 3; ++c) {
            double exact = std::exp(-sigma[c] * length);
            EXPECT_NEAR(mean[c], exact, 0.01 * exact) << "tau " << tau << " band " << c;
            EXPECT_LT(error[c], 0.0035 * exact) << "tau " << tau << " band " << c;
        }
    }
}

// A linear ramp σ_t = a·t on [0, d] under piecewise-constant majorants (1.5 times the ramp's top in each
// quarter): T = exp(−a d²/2), within 1% (standard error below 0.33%).
TEST(NullCollisions, RatioTrackingFollowsAVaryingExtinction) {
    double a = 1.5, d = 2.0;
    std::vector<MajorantSegment> segments;
    for (int k = 0; k < 4; ++k) segments.push_back({k * d / 4, (k + 1) * d / 4, 1.5 * a * (k + 1) * d / 4});
    Random random(9, 1);
    auto [mean, error] = meanOf(1000000, 1, [&](int) {
        return ratioTracking(segments, [&](double t) { return Spectrum(float(a * t), 1); }, random);
    });
    double exact = std::exp(-a * d * d / 2);
    EXPECT_NEAR(mean[0], exact, 0.01 * exact);
    EXPECT_LT(error[0], 0.0033 * exact);
}

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
    EXPECT_EQ(ratioTracking(segments, [](double) -> Spectrum { throw 0; }, random)[1], 1.f);
    EXPECT_FALSE(deltaTracking(segments, [](double) -> Spectrum { throw 0; }, weight, random));
    EXPECT_EQ(weight[2], 1.f);
}
