#include "cal/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace brume::cal {
namespace {

struct Stats {
    double mean = 0, sd = 0, min = 1e9, max = -1e9;
};

// Statistics of f over random points of the plane z = 0.37 within +-100, as measured for Radiance.
template <class F>
Stats sample(F f) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-100, 100);
    constexpr int n = 50000;
    Stats s;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        double v = f(u(rng), u(rng), .37);
        sum += v;
        sum2 += v * v;
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
    }
    s.mean = sum / n;
    s.sd = std::sqrt(sum2 / n - s.mean * s.mean);
    return s;
}

// Radiance 6.1's rtrace on a glow plane with brightfunc noise3(Px, Py, .37) (and noise3x, fnoise3),
// 20000 random points within +-100: standard deviations 0.277 (noise3), 0.673 (noise3x), 0.333
// (fnoise3); extremes -0.81..0.92, -2.74..2.61 and -1.24..1.25.
TEST(CalNoise, Noise3HasTheSpreadOfRadiances) {
    Stats s = sample(perlinNoise);
    EXPECT_NEAR(s.mean, 0, .01);
    EXPECT_NEAR(s.sd, .277, .015);
    EXPECT_GT(s.min, -1.05);
    EXPECT_LT(s.max, 1.05);
}

TEST(CalNoise, Noise3GradientHasTheSpreadOfRadiances) {
    Stats s = sample([](double x, double y, double z) { return perlinNoiseAndGradient(x, y, z)[1]; });
    EXPECT_NEAR(s.sd, .673, .03);
    EXPECT_LT(std::max(-s.min, s.max), 3.5);
}

TEST(CalNoise, FractalNoiseHasTheSpreadOfRadiances) {
    Stats s = sample(fractalNoise);
    EXPECT_NEAR(s.mean, 0, .02);
    EXPECT_NEAR(s.sd, .333, .02);
    EXPECT_LT(std::max(-s.min, s.max), 1.6);
}

TEST(CalNoise, Noise3IsZeroOnTheLatticeAndSmoothBetween) {
    EXPECT_EQ(perlinNoise(3, -7, 12), 0);
    EXPECT_NEAR(perlinNoise(3.5, 2.25, 1e-9), perlinNoise(3.5, 2.25, 0), 1e-8);
}

TEST(CalNoise, GradientIsTheDerivativeOfTheValue) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-20, 20);
    const double h = 1e-6;
    for (int i = 0; i < 200; ++i) {
        double p[3] = {u(rng), u(rng), u(rng)};
        auto g = perlinNoiseAndGradient(p[0], p[1], p[2]);
        EXPECT_EQ(g[0], perlinNoise(p[0], p[1], p[2]));
        for (int k = 0; k < 3; ++k) {
            double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
            a[k] += h;
            b[k] -= h;
            double numeric = (perlinNoise(a[0], a[1], a[2]) - perlinNoise(b[0], b[1], b[2])) / (2 * h);
            EXPECT_NEAR(g[1 + k], numeric, 1e-6);
        }
    }
}

TEST(CalNoise, FractalNoiseIsContinuousAndDeterministic) {
    EXPECT_EQ(fractalNoise(1.25, 2.5, 3.75), fractalNoise(1.25, 2.5, 3.75));
    EXPECT_NEAR(fractalNoise(1.25, 2.5, 3.75), fractalNoise(1.25 + 1e-9, 2.5, 3.75), 1e-5);
    EXPECT_NE(fractalNoise(1.25, 2.5, 3.75), fractalNoise(1.3, 2.5, 3.75));
}

TEST(CalNoise, HugeAndNonFiniteCoordinatesAreHandled) {
    EXPECT_TRUE(std::isfinite(perlinNoise(1e300, -1e300, 5e15)));
    EXPECT_TRUE(std::isfinite(fractalNoise(1e15, 2, 3)));
    EXPECT_TRUE(std::isnan(perlinNoise(NAN, 0, 0)));
    EXPECT_TRUE(std::isnan(fractalNoise(INFINITY, 0, 0)));
}

}  // namespace
}  // namespace brume::cal
