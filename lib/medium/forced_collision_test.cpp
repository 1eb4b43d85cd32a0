// The distance distributions of in-scattering: each is one strategy of a mixture whose weights are the densities
// the distributions report and whose draws invert their cumulative distributions, so every draw must land in
// the segments, and the reported density must be the one the draws follow and integrate to 1 there (an error in
// either biases the in-scattered light).
#include "medium/forced_collision.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <vector>

using namespace brume;

namespace {

// Two stretches of medium with a gap between them, as a ray crossing two puffs of smoke sees them.
const std::vector<MajorantSegment> kSegments = {{0.5, 2.0, 0.8, 0.1}, {2.0, 3.0, 3.0, 3.0}, {4.5, 9.0, 0.2, 0.0}};

// ∫ density over [lo, hi] (Simpson's rule, fine enough for the densities' smooth pieces).
double integral(const std::function<double(double)>& density, double lo, double hi) {
    const int n = 20000;
    double h = (hi - lo) / n, sum = density(lo) + density(hi);
    for (int i = 1; i < n; ++i) sum += density(lo + i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

// Draws land inside the segments, the density is 0 outside them and integrates to 1 over them, and the
// share of 400000 draws in each of 12 bins matches the density's integral there within 5 standard errors
// (about 1e-3 of all draws each: a density off by a few % in any bin fails).
void expectDrawsFollowTheDensity(const std::function<double(double)>& sample,
                                 const std::function<double(double)>& density) {
    double total = 0;
    for (const MajorantSegment& s : kSegments) total += integral(density, s.t0, s.t1);
    EXPECT_NEAR(total, 1.0, 1e-4);  // (Simpson's ends meet the jumps between segments: ~1e-5)
    EXPECT_EQ(density(0.2), 0.0);
    EXPECT_EQ(density(3.7), 0.0);
    EXPECT_EQ(density(9.5), 0.0);
    const double lo = 0.5, hi = 9.0;
    const int bins = 12, draws = 400000;
    std::vector<int> counts(bins, 0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int i = 0; i < draws; ++i) {
        double t = sample((i + uniform(rng)) / draws);
        bool inside = false;
        for (const MajorantSegment& s : kSegments) inside = inside || (t >= s.t0 && t <= s.t1);
        ASSERT_TRUE(inside) << t;
        counts[std::min(bins - 1, int((t - lo) / (hi - lo) * bins))]++;
    }
    for (int b = 0; b < bins; ++b) {
        double p = integral(density, lo + b * (hi - lo) / bins, lo + (b + 1) * (hi - lo) / bins);
        double sigma = std::sqrt(p * (1 - p) / draws);
        EXPECT_NEAR(counts[b] / double(draws), p, 5 * sigma + 1e-6) << "bin " << b;
    }
}

// Draws of one distribution alone, through a mixture of it (how inScattered draws): stratified numbers in
// order, each searched for from the last draw.
template <class Distribution>
void expectDrawsFollowItsDensity(const Distribution& d) {
    DistanceMixture alone(kSegments.front().t0, kSegments.back().t1);
    alone.add(1, &d);
    double last = -std::numeric_limits<double>::infinity();
    expectDrawsFollowTheDensity([&](double u) { return last = alone.sample(u, last); },
                                [&](double t) { return d.cdfAndDensity(t).density; });
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

// Toward a point beside the ray, one beyond its end, and one nearly on it (h held at minDistance); plain, and
// shaped by forward and backward Henyey–Greenstein phase functions.
TEST(EquiangularCollision, DrawsFallAsTheInverseSquareFromThePointTimesThePhase) {
    const Ray ray(dvec3(1, 2, 3), glm::normalize(dvec3(1, -1, 2)));
    for (double g : {0.0, 0.6, -0.4})
        for (dvec3 point : {ray.org + 2.5 * ray.dir + dvec3(0.3, 0.3, 0), ray.org + 12.0 * ray.dir + dvec3(0, 2, 1),
                            ray.org + 6.0 * ray.dir}) {
            SCOPED_TRACE(g);
            EquiangularCollision toward(kSegments, ray, point, 0.05, HenyeyGreenstein(g));
            double h = toward.distanceFromRay();
            EXPECT_GE(h, 0.05);
            if (g == 0) {  // ∫ σ̄ h / (h² + (t − t_c)²) dt / 4π over the segments
                double t_c = glm::dot(point - ray.org, ray.dir), angle = 0;
                for (const MajorantSegment& s : kSegments)
                    angle += s.majorant * (std::atan((s.t1 - t_c) / h) - std::atan((s.t0 - t_c) / h));
                EXPECT_NEAR(toward.phaseAngle(), angle / (4 * std::numbers::pi), 1e-12);
            }
            expectDrawsFollowItsDensity(toward);
        }
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

// A mixture of all three, drawn by inverting its cumulative distribution, with stratified numbers in order
// (each draw searched for from the last, as inScattered draws them): the draws follow the mixture's density.
TEST(DistanceMixture, DrawsFollowTheMixturesDensity) {
    const Ray ray(dvec3(1, 2, 3), glm::normalize(dvec3(1, -1, 2)));
    ForcedCollision forced(kSegments);
    UniformCollision even(kSegments);
    EquiangularCollision toward(kSegments, ray, ray.org + 2.5 * ray.dir + dvec3(0.3, 0.3, 0), 0.05,
                                HenyeyGreenstein(0.6));
    DistanceMixture mixture(kSegments.front().t0, kSegments.back().t1);
    mixture.add(0.8, &toward);
    mixture.add(0.05, &even);
    mixture.add(0.15, &forced);
    mixture.add(0, &even);  // (no share: left out)
    double last = -std::numeric_limits<double>::infinity();
    expectDrawsFollowTheDensity([&](double u) { return last = mixture.sample(u, last); },
                                [&](double t) { return mixture.density(t); });
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

