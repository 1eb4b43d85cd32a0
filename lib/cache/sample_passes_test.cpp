#include "cache/sample_passes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "cache/sphere_samples.h"
#include "sampling/random.h"

using namespace brume;

namespace {

// `passes` passes of a record's samples, each stratum's radiance drawn by `draw`.
SphereSamples samplesOf(int passes, Random& rng, const std::function<double(Random&)>& draw) {
    SphereSamples s(dvec3(0), 1024, 1);
    for (int p = 0; p < passes; ++p) {
        int pass = p == 0 ? 0 : s.addPass();
        for (int j = 0; j < s.rows(); ++j)
            for (int k = 0; k < s.columns(); ++k)
                s.set(s.cell(j, k, pass), s.direction(j, k, 0.5, 0.5), Spectrum(float(draw(rng)), 1), 1);
    }
    return s;
}

double exponential(Random& rng) { return -std::log(1 - rng.uniform()); }

}  // namespace

// Where the light is the same in every stratum, the triples' estimate of the mean's variance is unbiased:
// over 400 records of exponential samples (mean 1, variance 1) its mean is 1/N, N the samples, in one pass or
// three. Each record's estimate (about 340 triples, each d² of relative spread about 2) spreads by some 11 %:
// 400 of them by 0.6 %; the tolerance, 3 %, is 5 of those.
TEST(RaySamples, NeighbouringStrataGiveTheVarianceOfTheMean) {
    Random rng(7);
    for (int passes : {1, 3}) {
        double sum = 0;
        int count = 0;
        for (int trial = 0; trial < 400; ++trial) {
            SphereSamples s = samplesOf(passes, rng, exponential);
            double se = s.meanStandardError();
            sum += se * se * s.count();
            count = s.count();
        }
        EXPECT_NEAR(sum / 400, 1.0, 0.03) << passes << " passes of " << count / passes;
    }
    // No noise, no error: the same light everywhere.
    EXPECT_EQ(samplesOf(2, rng, [](Random&) { return 3.0; }).meanStandardError(), 0.0);
}

// Light that changes smoothly across the strata is not noise: 2 + ω_x, without noise, over 32 × 32 strata,
// gives a relative error of about (2π/32)² / √1024 / 2 ≈ 6e-4 (the curvature over three columns; pairs
// would count its slope: about 3e-3).
TEST(RaySamples, SmoothLightIsNotNoise) {
    SphereSamples s(dvec3(0), 1024, 1);
    for (int j = 0; j < s.rows(); ++j)
        for (int k = 0; k < s.columns(); ++k) {
            dvec3 d = s.direction(j, k, 0.5, 0.5);
            s.set(s.cell(j, k), d, Spectrum(float(2 + d.x), 1), 1);
        }
    EXPECT_LT(s.meanStandardError() / s.meanBrightness(), 1e-3);
}

TEST(SamplePasses, AsManyAsBringTheErrorUnderTheTarget) {
    EXPECT_EQ(samplePasses(0.01, 0.01), 1);
    EXPECT_EQ(samplePasses(0.0, 0.01), 1);
    EXPECT_EQ(samplePasses(0.02, 0.01), 4);
    EXPECT_EQ(samplePasses(0.021, 0.01), 5);
    EXPECT_EQ(samplePasses(1.0, 0.01), kMaxSamplePasses);
    EXPECT_EQ(samplePasses(0.5, 0.0), 1);  // no target: -aa 0 makes no records, but never divide by it
    EXPECT_EQ(samplePasses(std::nan(""), 0.01), 1);
}

// Deciding the passes once from the first keeps a record's mean nearly unbiased even where the light is rare
// bright paths (the first pass's error, and so the passes, follow its own mean): samples of 50 with
// probability 1/50 (mean 1; a pass's relative error ≈ 22 %), a target of 12 %, so that 2 to 8 passes are
// decided (4 on average). Over 4000 records the mean of their values is 1 within 4 standard errors of that
// mean (≈ 0.2 %) plus the bias such a rule has, Cov(first pass, 1/passes) ≈ 1.4 % here (1.2 % measured): a
// sixteenth of the error a single pass makes, where the passes halve that error.
TEST(SamplePasses, DecidingOnceFromTheFirstPassKeepsTheMeanNearlyUnbiased) {
    Random rng(11);
    auto rare = [](Random& r) { return r.uniform() < 0.02 ? 50.0 : 0.0; };
    const int trials = 4000;
    double sum = 0, sum2 = 0, firstSquares = 0, finalSquares = 0, passesSum = 0;
    for (int trial = 0; trial < trials; ++trial) {
        SphereSamples first = samplesOf(1, rng, rare);
        double f1 = first.meanBrightness();
        int passes = f1 > 0 ? samplePasses(first.meanStandardError() / f1, 0.12) : kMaxSamplePasses;
        double rest = passes > 1 ? samplesOf(passes - 1, rng, rare).meanBrightness() : 0;
        double value = (f1 + (passes - 1) * rest) / passes;
        sum += value, sum2 += value * value, passesSum += passes;
        firstSquares += (f1 - 1) * (f1 - 1), finalSquares += (value - 1) * (value - 1);
    }
    double mean = sum / trials, spread = std::sqrt((sum2 / trials - mean * mean) / trials);
    double firstError = std::sqrt(firstSquares / trials), finalError = std::sqrt(finalSquares / trials);
    EXPECT_GT(passesSum / trials, 2.0);
    EXPECT_LT(passesSum / trials, 7.0);
    EXPECT_NEAR(mean, 1.0, 4 * spread + 0.015) << "first pass's error " << firstError;
    EXPECT_LT(finalError, 0.65 * firstError);
}
