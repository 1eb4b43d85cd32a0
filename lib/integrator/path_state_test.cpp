// Russian roulette ends paths where Radiance's -lw and a negative -lr would cut them, without bias: a path
// that goes on is boosted by the inverse of its chance, so E[boost · 1{goes on}] = 1. A positive -lr cuts
// them as Radiance does.
#include "integrator/path_state.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/testing.h"

using namespace brume;
using integrator_testing::Mean;

namespace {

constexpr int kPlays = 20000;

// What n plays of the roulette at `parent` give: boost · 1{goes on} (its mean is the expected weight kept),
// and how often the path went on.
struct Plays {
    Mean kept;
    int survivors = 0;
    double wentOn() const { return double(survivors) / kPlays; }
};

Plays play(const RussianRoulette& roulette, const PathState& parent, float coef, bool reflection,
           bool byReflectance = false, int rays = 1) {
    Random rng(17, 3);
    Plays plays;
    for (int i = 0; i < kPlays; ++i) {
        PathState child;
        float boost;
        bool on = roulette.spawn(parent, child, Spectrum(coef), reflection, rng, boost, byReflectance, rays);
        plays.kept.add(on ? boost : 0.0);
        plays.survivors += on;
    }
    return plays;
}

// The roulette is fair where paths go on with probability p: the weight kept is 1 (within 4 standard
// errors of its mean) and the paths go on a fraction p of the time (within 4 standard deviations of a
// binomial frequency).
void expectFair(const Plays& plays, double p) {
    EXPECT_NEAR(plays.kept.value(), 1.0, 4 * plays.kept.standardError());
    EXPECT_NEAR(plays.wentOn(), p, 4 * std::sqrt(p * (1 - p) / kPlays));
}

PathState withWeight(double weight, int reflections = 0) {
    PathState s;
    s.weight = weight;
    s.reflections = reflections;
    return s;
}

}  // namespace

TEST(RussianRoulette, TheChildCarriesTheScatteringsWeightDepthAndReflections) {
    RussianRoulette roulette(-10, 1e-4);
    PathState parent = withWeight(0.5, 2);
    parent.depth = 3, parent.viaMirror = 7;
    PathState child;
    float boost;
    Random rng;
    ASSERT_TRUE(roulette.spawn(parent, child, Spectrum(0.4f), true, rng, boost));
    EXPECT_DOUBLE_EQ(child.weight, 0.5 * 0.4f);
    EXPECT_EQ(child.reflections, 3);
    EXPECT_EQ(child.depth, 4);
    EXPECT_EQ(child.viaMirror, -1);  // a mirror's image serves only the ray it reflected
    EXPECT_EQ(boost, 1.f);
    // Coefficients above 1 (a light-emitting or amplifying lobe) do not raise the weight past the parent's.
    ASSERT_TRUE(roulette.spawn(parent, child, Spectrum(3.f), false, rng, boost));
    EXPECT_DOUBLE_EQ(child.weight, 0.5);
    EXPECT_EQ(child.reflections, 2);  // a transmission is no reflection
}

// The -ad paths of a first bounce share their parent's estimate: under roulette each weighs 1/paths of it (its
// contribution to the answer, as Radiance's path-traced ambient rays), down to -lw; a hard -lr keeps the
// undivided weight, which its hard -lw cut compares.
TEST(RussianRoulette, PathsThatShareAnEstimateShareItsWeight) {
    PathState child;
    float boost;
    Random rng;
    ASSERT_TRUE(RussianRoulette(-10, 1e-4).spawn(withWeight(0.5), child, Spectrum(0.4f), true, rng, boost, false, 256));
    EXPECT_DOUBLE_EQ(child.weight, 0.5 * 0.4f / 256);
    EXPECT_EQ(boost, 1.f);
    ASSERT_TRUE(RussianRoulette(7, 1e-4).spawn(withWeight(0.5), child, Spectrum(0.4f), true, rng, boost, false, 256));
    EXPECT_DOUBLE_EQ(child.weight, 0.5 * 0.4f);
    // The split alone takes no path below -lw (the roulette would play once for all of them).
    Plays split = play(RussianRoulette(-10, 0.01), withWeight(1), 0.5f, true, false, 250);
    EXPECT_EQ(split.wentOn(), 1.0);
    EXPECT_EQ(split.kept.value(), 1.0);
    ASSERT_TRUE(RussianRoulette(-10, 0.01).spawn(withWeight(1), child, Spectrum(0.5f), true, rng, boost, false, 250));
    EXPECT_DOUBLE_EQ(child.weight, 0.01);
}

// Below -lw (.01) a path of weight .002 goes on with probability .2, and then has weight -lw.
TEST(RussianRoulette, BelowTheMinimumWeightKeepsTheExpectedWeight) {
    RussianRoulette roulette(-10, 0.01);
    expectFair(play(roulette, withWeight(0.004), 0.5f, true), 0.2);
    PathState child;
    float boost = 0;
    Random rng(5);
    while (!roulette.spawn(withWeight(0.004), child, Spectrum(0.5f), true, rng, boost)) {}
    EXPECT_NEAR(child.weight, 0.01, 1e-12);
    EXPECT_FLOAT_EQ(boost, 5.f);
    // Above -lw nothing is played.
    Plays above = play(roulette, withWeight(1), 0.5f, true);
    EXPECT_EQ(above.wentOn(), 1.0);
    EXPECT_EQ(above.kept.value(), 1.0);
}

// -lr -3: up to 3 reflections paths go on; past them they go on with the reflectance's chance (at most .95,
// so that perfect mirrors end paths too). Transmissions are not counted.
TEST(RussianRoulette, PastTheReflectionsOfANegativeLrKeepsTheExpectedWeight) {
    RussianRoulette roulette(-3, 1e-4);
    EXPECT_EQ(play(roulette, withWeight(1, 2), 0.6f, true).wentOn(), 1.0);
    expectFair(play(roulette, withWeight(1, 3), 0.6f, true), 0.6);
    expectFair(play(roulette, withWeight(1, 3), 1.0f, true), 0.95);
    EXPECT_EQ(play(roulette, withWeight(1, 3), 0.6f, false).wentOn(), 1.0);
}

// -lr 2: the third reflection ends the path, always; transmissions go on; and so does nothing below -lw.
TEST(RussianRoulette, PositiveLrIsAHardLimitCountingReflectionsOnly) {
    RussianRoulette roulette(2, 0.01);
    EXPECT_EQ(play(roulette, withWeight(1, 1), 0.6f, true).wentOn(), 1.0);
    EXPECT_EQ(play(roulette, withWeight(1, 2), 0.6f, true).wentOn(), 0.0);
    EXPECT_EQ(play(roulette, withWeight(1, 2), 0.6f, false).wentOn(), 1.0);
    EXPECT_EQ(play(roulette, withWeight(0.004, 0), 0.5f, false).wentOn(), 0.0);
}

// Paths past -ab bounces play by the reflectance from their first reflection on, whatever count a negative
// or zero -lr allows; and with -lr 0 (no count) every path plays past 64 reflections, so that a closed box of
// perfect mirrors still ends its paths.
TEST(RussianRoulette, ByReflectancePlaysWhateverTheReflectionsAllowed) {
    for (int lr : {-100, 0}) {
        RussianRoulette roulette(lr, 1e-4);
        expectFair(play(roulette, withWeight(1), 0.7f, true, true), 0.7);
        expectFair(play(roulette, withWeight(1), 0.7f, false, true), 0.7);
        EXPECT_EQ(play(roulette, withWeight(1), 0.7f, true).wentOn(), 1.0) << lr;
    }
    RussianRoulette noCount(0, 1e-4);
    EXPECT_EQ(play(noCount, withWeight(1, 63), 1.0f, true).wentOn(), 1.0);
    expectFair(play(noCount, withWeight(1, 64), 1.0f, true), 0.95);
}
