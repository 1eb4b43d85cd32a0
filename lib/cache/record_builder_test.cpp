// Records from synthetic hemispheres whose irradiance, gradients and curvature are known in closed form.
#include "cache/record_builder.h"

#include <gtest/gtest.h>

#include <functional>
#include <numbers>

#include "sampling/random.h"

using namespace brume;
using std::numbers::pi;

namespace {

// What a sample along `dir` from `p` sees: radiance (grey) and distance.
using Environment = std::function<std::pair<double, double>(const dvec3& p, const dvec3& dir)>;

// `passes` passes over the strata, each with the jitter of `seed` (the same in every pass) or fresh jitter.
HemisphereSamples sample(const dvec3& p, const dvec3& n, int divisions, const Environment& env, uint64_t seed = 7,
                         int passes = 1, bool sameJitter = false) {
    HemisphereSamples hs(p, n, divisions, 3);
    Random rng(seed);
    for (int pass = 0; pass < passes; ++pass) {
        if (pass > 0) hs.addPass();
        if (sameJitter) rng = Random(seed);
        for (int j = 0; j < hs.rows(); ++j)
            for (int k = 0; k < hs.columns(); ++k) {
                dvec3 dir = hs.direction(j, k, rng.uniform(), rng.uniform());
                auto [l, d] = env(p, dir);
                hs.set(hs.cell(j, k, pass), dir, Spectrum(float(l)), d);
            }
    }
    return hs;
}

// A ceiling at height h, bright (L = 1) where x > 0, black elsewhere. Facing up at (x, 0, 0):
// E(x) = (π/2)(1 + x/√(x² + h²)), so E(0) = π/2 and dE/dx = π/(2h).
Environment halfLitCeiling(double h) {
    return [h](const dvec3& p, const dvec3& dir) -> std::pair<double, double> {
        double t = (h - p.z) / dir.z;
        return {p.x + t * dir.x > 0 ? 1.0 : 0.0, t};
    };
}

RecordShape shape(RecordShape::Kind kind = RecordShape::Kind::Adaptive) {
    RecordShape s;
    s.kind = kind;
    s.accuracy = 0.1;
    s.minRadius = 0.01;
    s.maxRadius = 10;
    return s;
}

}  // namespace

// Stratified cosine sampling of a uniform sky: E = πL exactly, no gradient, no curvature (largest zone).
TEST(RecordBuilder, UniformSkyGivesPiLAndTheLargestZone) {
    auto hs = sample(dvec3(0), dvec3(0, 0, 1), 1024, [](const dvec3&, const dvec3&) {
        return std::pair{2.0, std::numeric_limits<double>::infinity()};
    });
    SurfaceRecord r = buildRecord(hs, shape(), 0);
    EXPECT_NEAR(r.value(SurfaceRecord::kIrradiance, 0), 2 * pi, 1e-4);
    EXPECT_NEAR(r.value(SurfaceRecord::kAlongK1, 0), 0, 1e-6);
    EXPECT_NEAR(r.value(SurfaceRecord::kAlongK2, 0), 0, 1e-6);
    EXPECT_FLOAT_EQ(r.radius[0], 10);
    EXPECT_FLOAT_EQ(r.radius[1], 10);
    EXPECT_EQ(r.channels(), 3);
}

// Ward and Heckbert's occlusion-aware gradient against the closed form. Tolerances: 2% on E (1024
// stratified samples across one edge), 8% on the gradient (it only sees the edge's cells).
TEST(RecordBuilder, TranslationalGradientMatchesAHalfLitCeiling) {
    const double h = 2;
    auto hs = sample(dvec3(0), dvec3(0, 0, 1), 2048, halfLitCeiling(h));
    SurfaceRecord r = buildRecord(hs, shape(), 0);
    EXPECT_NEAR(r.value(SurfaceRecord::kIrradiance, 0), pi / 2, 0.02 * pi / 2);
    dvec3 gradient = double(r.value(SurfaceRecord::kAlongK1, 0)) * r.axis +
                     double(r.value(SurfaceRecord::kAlongK2, 0)) * r.axis2();
    EXPECT_NEAR(gradient.x, pi / (2 * h), 0.08 * pi / (2 * h));
    EXPECT_NEAR(gradient.y, 0, 0.05 * pi / (2 * h));
    // The zone is shortest across the edge (within 45°: the curvature bound does not see the edge itself).
    EXPECT_GT(std::abs(r.axis.x), 0.7);
    EXPECT_LT(r.radius[0], r.radius[1]);
}

// A record of several passes over its strata is their mean, gradients included: two passes of the very
// same rays give the one pass's record (to float rounding); four passes of fresh jitter, 512 strata each,
// the closed form within the tolerances above (2048 rays in all).
TEST(RecordBuilder, PassesOverTheStrataAverage) {
    const double h = 2;
    SurfaceRecord once = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 512, halfLitCeiling(h)), shape(), 0);
    SurfaceRecord twice = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 512, halfLitCeiling(h), 7, 2, true), shape(), 0);
    ASSERT_EQ(once.values.size(), twice.values.size());
    for (size_t i = 0; i < once.values.size(); ++i)
        EXPECT_NEAR(twice.values[i], once.values[i], 1e-5 * (1 + std::abs(once.values[i]))) << "field " << i;
    EXPECT_NEAR(twice.radius[0], once.radius[0], 1e-5 * once.radius[0]);
    SurfaceRecord r = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 512, halfLitCeiling(h), 7, 4), shape(), 0);
    EXPECT_NEAR(r.value(SurfaceRecord::kIrradiance, 0), pi / 2, 0.02 * pi / 2);
    dvec3 gradient = double(r.value(SurfaceRecord::kAlongK1, 0)) * r.axis +
                     double(r.value(SurfaceRecord::kAlongK2, 0)) * r.axis2();
    EXPECT_NEAR(gradient.x, pi / (2 * h), 0.08 * pi / (2 * h));
    EXPECT_NEAR(gradient.y, 0, 0.05 * pi / (2 * h));
}

// A sky of radiance 1 + ω_x: tilting the normal n toward x gives E(n) = π + (2π/3) n_x. Tolerance 5%:
// the estimator weighs samples by tan θ, noisy near the horizon.
TEST(RecordBuilder, RotationalGradientMatchesALinearSky) {
    auto hs = sample(dvec3(0), dvec3(0, 0, 1), 2048, [](const dvec3&, const dvec3& dir) {
        return std::pair{1 + dir.x, std::numeric_limits<double>::infinity()};
    });
    SurfaceRecord r = buildRecord(hs, shape(), 0);
    dvec3 tilt = double(r.value(SurfaceRecord::kTiltK1, 0)) * r.axis +
                 double(r.value(SurfaceRecord::kTiltK2, 0)) * r.axis2();
    EXPECT_NEAR(tilt.x, 2 * pi / 3, 0.05 * 2 * pi / 3);
    EXPECT_NEAR(tilt.y, 0, 0.05 * 2 * pi / 3);
}

// Zones scale with distance to what the point sees: a room twice as large gives zones twice as large.
TEST(RecordBuilder, ZonesScaleWithTheDistanceToSurroundingSurfaces) {
    auto box = [](double size) {
        return [size](const dvec3& p, const dvec3& dir) -> std::pair<double, double> {
            double t = std::numeric_limits<double>::infinity();
            for (int a = 0; a < 3; ++a) {
                double bound = dir[a] > 0 ? size : -size;
                if (dir[a] != 0) t = std::min(t, (bound - p[a]) / dir[a]);
            }
            return {0.5, t};
        };
    };
    for (auto kind : {RecordShape::Kind::Adaptive, RecordShape::Kind::Classic}) {
        SurfaceRecord small = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 512, box(1)), shape(kind), 0);
        SurfaceRecord large = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 512, box(2)), shape(kind), 0);
        EXPECT_NEAR(large.radius[0] / small.radius[0], 2, 0.02);
        EXPECT_NEAR(large.radius[1] / small.radius[1], 2, 0.02);
    }
    // Classic: ε times the harmonic mean distance, a circle.
    auto hs = sample(dvec3(0), dvec3(0, 0, 1), 512, box(1));
    SurfaceRecord classic = buildRecord(hs, shape(RecordShape::Kind::Classic), 0);
    double inverse = 0;
    for (int i = 0; i < hs.count(); ++i) inverse += 1 / hs.distance(i);
    EXPECT_NEAR(classic.radius[0], 0.1 * hs.count() / inverse, 1e-5);
    EXPECT_EQ(classic.radius[0], classic.radius[1]);
}

// The equivalent point sources shorten a zone that would reach a nearby bright patch it cannot describe.
TEST(RecordBuilder, ZonesShortenWhereTheEquivalentSourcesDisagree) {
    auto lampNear = [](const dvec3& p, const dvec3& dir) -> std::pair<double, double> {
        double t = (0.3 - p.z) / dir.z;  // a low ceiling, bright in a small patch beside the point
        dvec3 hit = p + t * dir;
        bool lit = std::abs(hit.x - 0.4) < 0.1 && std::abs(hit.y) < 0.1;
        return {lit ? 50.0 : 0.2, t};
    };
    SurfaceRecord r = buildRecord(sample(dvec3(0), dvec3(0, 0, 1), 2048, lampNear), shape(), 0);
    EXPECT_LT(r.radius[0], 0.3);  // well under the distance to the patch's edge
    EXPECT_GT(r.radius[0], 0);
}

// An aimed sample is an equivalent point source: under a dark hemisphere, a lamp's irradiance E at distance d
// along ω (θ from the normal) adds E to the record, moves it by 3E(ω·s)/d along the tangent s (∂/∂x of
// I cos θ / d²) and tilts it by E tan θ; and its closeness shrinks the zone, which rays alone would leave
// at its largest.
TEST(RecordBuilder, AimedSamplesCountAsEquivalentPointSources) {
    auto dark = [](const dvec3&, const dvec3&) { return std::pair{0.0, std::numeric_limits<double>::infinity()}; };
    HemisphereSamples hs = sample(dvec3(0), dvec3(0, 0, 1), 256, dark);
    SurfaceRecord without = buildRecord(hs, shape(), 0);
    const double theta = 0.5, d = 0.8, e = 3;
    dvec3 omega(std::sin(theta), 0, std::cos(theta));
    hs.aimed().push_back({omega, Spectrum(float(e)), d});
    SurfaceRecord r = buildRecord(hs, shape(), 0);
    EXPECT_NEAR(r.value(SurfaceRecord::kIrradiance, 0), e, 1e-5);
    dvec3 along = double(r.value(SurfaceRecord::kAlongK1, 0)) * r.axis + double(r.value(SurfaceRecord::kAlongK2, 0)) * r.axis2();
    dvec3 tilt = double(r.value(SurfaceRecord::kTiltK1, 0)) * r.axis + double(r.value(SurfaceRecord::kTiltK2, 0)) * r.axis2();
    EXPECT_NEAR(along.x, 3 * e * std::sin(theta) / d, 1e-4);
    EXPECT_NEAR(along.y, 0, 1e-5);
    EXPECT_NEAR(tilt.x, e * std::tan(theta), 1e-4);
    EXPECT_FLOAT_EQ(without.radius[0], 10);
    EXPECT_LT(std::max(r.radius[0], r.radius[1]), d);
}
