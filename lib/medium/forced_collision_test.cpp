// The distance distributions of in-scattering: each is one strategy of a mixture whose weights are the densities
// the distributions report and whose draws invert their cumulative distributions, so every draw must land in
// the segments, and the reported density must be the one the draws follow and integrate to 1 there (an error in
// either biases the in-scattered light).
#include "medium/forced_collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "sampling/testing.h"

using namespace brume;

namespace {

// Two stretches of medium with a gap between them, as a ray crossing two puffs of smoke sees them.
const std::vector<MajorantSegment> kSegments = {{0.5, 2.0, 0.8, 0.1}, {2.0, 3.0, 3.0, 3.0}, {4.5, 9.0, 0.2, 0.0}};
// A ray along them, and a point beside it by the joint of its first two segments (0.42 from it).
const Ray kRay(dvec3(1, 2, 3), glm::normalize(dvec3(1, -1, 2)));
const dvec3 kBeside = kRay.org + 2.5 * kRay.dir + dvec3(0.3, 0.3, 0);

// ∫ density over [lo, hi] (Simpson's rule, fine enough for the densities' smooth pieces).
double integral(const std::function<double(double)>& density, double lo, double hi) {
    const int n = 20000;
    double h = (hi - lo) / n, sum = density(lo) + density(hi);
    for (int i = 1; i < n; ++i) sum += density(lo + i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

// The density integrates to 1 over the segments and is 0 outside them; draws land inside the segments and follow
// the density (chi-square, sampling/testing.h: 2×10⁵ draws in 100 bins over [0.5, 9], the gap between the
// segments included: a density 5% off over a tenth of the draws fails).
void expectDrawsFollowTheDensity(const std::function<double(double)>& sample,
                                 const std::function<double(double)>& density) {
    double total = 0;
    for (const MajorantSegment& s : kSegments) total += integral(density, s.t0, s.t1);
    EXPECT_NEAR(total, 1.0, 1e-4);  // (Simpson's ends meet the jumps between segments: ~1e-5)
    EXPECT_EQ(density(0.2), 0.0);
    EXPECT_EQ(density(3.7), 0.0);
    EXPECT_EQ(density(9.5), 0.0);
    int outside = 0;
    auto draw = [&](double u) -> std::optional<double> {
        double t = sample(u);
        outside += std::none_of(kSegments.begin(), kSegments.end(),
                                [t](const MajorantSegment& s) { return t >= s.t0 && t <= s.t1; });
        return t;
    };
    sampling::testing::expectSamplesFollowDensity(draw, density, {.lo = 0.5, .hi = 9.0, .draws = 200'000});
    EXPECT_EQ(outside, 0) << "draws outside the segments";
}

// inScattered draws stratified numbers in order, each searched for from the last draw: a draw so searched for
// lands where a search from the start does (within what Newton's method leaves, 1e-10 of probability).
void expectSearchesFromTheLastDrawAgree(const DistanceMixture& mixture) {
    double last = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < 1000; ++i) {
        double u = (i + 0.5) / 1000, t = mixture.sample(u, last);
        EXPECT_NEAR(t, mixture.sample(u), 1e-6 * (1 + t)) << "u " << u;
        last = t;
    }
}

// Draws of one distribution alone, through a mixture of it (how inScattered draws).
template <class Distribution>
void expectDrawsFollowItsDensity(const Distribution& d) {
    DistanceMixture alone(kSegments.front().t0, kSegments.back().t1);
    alone.add(1, &d);
    expectDrawsFollowTheDensity([&](double u) { return alone.sample(u); },
                                [&](double t) { return d.cdfAndDensity(t).density; });
    expectSearchesFromTheLastDrawAgree(alone);
}

}  // namespace

TEST(ForcedCollision, DrawsFollowTheMajorantsFirstCollisionWithinTheSegments) {
    ForcedCollision forced(kSegments);
    EXPECT_NEAR(forced.reach(), -std::expm1(-(0.8 * 1.5 + 3.0 + 0.2 * 4.5)), 1e-12);
    expectDrawsFollowItsDensity(forced);
}

TEST(UniformCollision, DrawsAreUniformOverTheSegmentsLength) {
    UniformCollision even(kSegments);
    EXPECT_DOUBLE_EQ(even.length(), 1.5 + 1.0 + 4.5);
    expectDrawsFollowItsDensity(even);
}

// Two smokes' densities over the segments' stretches (cubic pieces as trilinear cells give, an even stretch, a
// ramp after the gap), weighed by their extinctions per unit density: draws where the first real collision falls.
TEST(DepthCollision, DrawsFollowTheTrueExtinctionsFirstCollisionWithinTheSegments) {
    DensityProfile a, b;
    a.append(0.5, 1.2, {0.0, 0.4, 1.5, -0.6});
    a.append(1.2, 2.0, {0.9, -0.3, 0.0, 0.2});
    a.append(2.0, 3.0, 2.5);
    b.append(4.5, 9.0, {0.0, 0.3, 0, 0});
    b.append(0.5, 0.5, 7.0);  // empty: dropped
    EXPECT_EQ(b.pieces().size(), 1u);
    const double scaleA = 0.8, scaleB = 1.3;
    DepthCollision depth({{&a, scaleA}, {&b, scaleB}});
    EXPECT_NEAR(depth.reach(), -std::expm1(-(scaleA * a.total() + scaleB * b.total())), 1e-12);
    expectDrawsFollowItsDensity(depth);
    // One smoke's: the closed-form inverse lands where the mixture's search does.
    DepthCollision one({{&a, scaleA}});
    DistanceMixture alone(kSegments.front().t0, kSegments.back().t1);
    alone.add(1, &one);
    ASSERT_TRUE(one.invertible());
    EXPECT_FALSE(depth.invertible());
    for (int i = 0; i < 1000; ++i) {
        double u = (i + 0.5) / 1000;
        EXPECT_NEAR(one.sample(u), alone.sample(u), 1e-7) << u;
    }
}

// Toward a point beside the ray, one beyond its end, and one nearly on it (h held at minDistance); plain, and
// shaped by forward and backward Henyey–Greenstein phase functions.
TEST(EquiangularCollision, DrawsFallAsTheInverseSquareFromThePointTimesThePhase) {
    for (double g : {0.0, 0.6, -0.4})
        for (dvec3 point : {kBeside, kRay.org + 12.0 * kRay.dir + dvec3(0, 2, 1), kRay.org + 6.0 * kRay.dir}) {
            SCOPED_TRACE(g);
            EquiangularCollision toward(kSegments, kRay, point, 0.05, HenyeyGreenstein(g));
            double h = toward.distanceFromRay();
            EXPECT_GE(h, 0.05);
            if (g == 0) {  // ∫ σ̄ h / (h² + (t − t_c)²) dt / 4π over the segments
                double t_c = glm::dot(point - kRay.org, kRay.dir), angle = 0;
                for (const MajorantSegment& s : kSegments)
                    angle += s.majorant * (std::atan((s.t1 - t_c) / h) - std::atan((s.t0 - t_c) / h));
                EXPECT_NEAR(toward.phaseAngle(), angle / (4 * std::numbers::pi), 1e-12);
            }
            expectDrawsFollowItsDensity(toward);
        }
}

// Searched from the start (as inScattered searches for each ray's first draw), a draw of the forward lobe toward
// the point beside the ray lands where its u says: Newton's steps from the middle of [0.5, 9] alternated between
// t ≈ 1.90 and t ≈ 2.58 about the density's jump at the segments' joint (t = 2), and after 100 of them returned
// t = 1.9027, whose cumulative distribution is 0.328, for u = 0.5855 (0.2% of u off so; with 4×10⁵ draws the
// chi-square failed at p = 4e-8). Bisection where Newton stalls: within 1e-9 for u every 1e-4.
TEST(DistanceMixture, SearchFromTheStartConvergesNearAJump) {
    EquiangularCollision toward(kSegments, kRay, kBeside, 0.05, HenyeyGreenstein(0.6));
    DistanceMixture alone(kSegments.front().t0, kSegments.back().t1);
    alone.add(1, &toward);
    EXPECT_NEAR(alone.cdfAndDensity(alone.sample(0.5855)).cdf, 0.5855, 1e-9);
    int off = 0;
    for (int k = 0; k < 10000; ++k) off += std::abs(alone.cdfAndDensity(alone.sample((k + 0.5) / 1e4)).cdf - (k + 0.5) / 1e4) > 1e-9;
    EXPECT_EQ(off, 0);
    expectDrawsFollowItsDensity(toward);
}

// A ray out to infinity in a homogeneous medium: the angle reaches π/2 beyond the foot.
TEST(EquiangularCollision, InfiniteRayEndsAtAQuarterTurn) {
    const std::vector<MajorantSegment> open = {{0, std::numeric_limits<double>::infinity(), 0.1, 0.1}};
    const Ray ray(dvec3(0), dvec3(1, 0, 0));
    EquiangularCollision toward(open, ray, dvec3(3, 4, 0), 0.01, HenyeyGreenstein(0));
    EXPECT_NEAR(toward.phaseAngle() * 4 * std::numbers::pi / 0.1, std::numbers::pi / 2 + std::atan(3.0 / 4.0), 1e-12);
    DistanceMixture alone(0, std::numeric_limits<double>::infinity());
    alone.add(1, &toward);
    for (double u : {0.0, 0.3, 0.999999}) {
        double t = alone.sample(u);
        EXPECT_TRUE(t >= 0 && std::isfinite(t)) << u;
        EXPECT_GT(toward.cdfAndDensity(t).density, 0);
    }
}

// A mixture of all three, drawn by inverting its cumulative distribution: the draws follow the mixture's density.
TEST(DistanceMixture, DrawsFollowTheMixturesDensity) {
    ForcedCollision forced(kSegments);
    UniformCollision even(kSegments);
    EquiangularCollision toward(kSegments, kRay, kBeside, 0.05, HenyeyGreenstein(0.6));
    DistanceMixture mixture(kSegments.front().t0, kSegments.back().t1);
    mixture.add(0.8, &toward);
    mixture.add(0.05, &even);
    mixture.add(0.15, &forced);
    mixture.add(0, &even);  // (no share: left out)
    expectDrawsFollowTheDensity([&](double u) { return mixture.sample(u); },
                                [&](double t) { return mixture.density(t); });
    expectSearchesFromTheLastDrawAgree(mixture);
    EXPECT_NEAR(mixture.density(2.2),
                0.8 * toward.cdfAndDensity(2.2).density + 0.05 * even.cdfAndDensity(2.2).density +
                    0.15 * forced.cdfAndDensity(2.2).density,
                1e-12);
}

// Over a ray to infinity the search first finds an end beyond the draw.
TEST(DistanceMixture, InfiniteRaysAreBracketed) {
    const std::vector<MajorantSegment> open = {{0, std::numeric_limits<double>::infinity(), 0.1, 0.1}};
    ForcedCollision forced(open);
    DistanceMixture mixture(0, std::numeric_limits<double>::infinity());
    mixture.add(1, &forced);
    for (double u : {0.0, 0.5, 0.999999})
        EXPECT_NEAR(mixture.sample(u), -std::log1p(-u) / 0.1, 1e-6 * (1 - std::log1p(-u) / 0.1)) << u;
}

