// Light along a ray through a homogeneous medium (-me σ, -ma a) to a wall at distance d, in a uniform
// surrounding of radiance L (a tracer that answers every ray with L): the wall seen through the medium,
// e^{−σd} L, plus what the medium scatters toward the ray, a(1 − e^{−σd}) L (its phase function integrates to 1
// over the surrounding).
#include "integrator/media_transport.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/testing.h"

using namespace brume;
using namespace brume::integrator_testing;

namespace {

const std::string kWall = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                          "grey polygon wall 0 0 12 -5 2 -5 5 2 -5 5 2 5 -5 2 5\n";
const std::string kLamp = "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0.5 1 0.5 0.1\n";
constexpr double kSigma = 0.5, kD = 2;
constexpr float kL = 2;

RenderSettings medium(double albedo, int ab = 1) {
    RenderSettings s = test::fixedSeed();
    s.medium.extinction = Spectrum(float(kSigma));
    s.medium.albedo = Spectrum(float(albedo));
    s.ambientBounces = ab;
    s.ambientAccuracy = 0;
    return s;
}

// What lies behind and what the medium scatters in, for a medium of albedo a.
double furnace(double albedo) {
    double t = std::exp(-kSigma * kD);
    return kL * (t + albedo * (1 - t));
}

// The ray from the origin to the wall, d away, with the medium along it; every other ray brings `surrounding`.
struct ToTheWall {
    Parts& parts;
    Ray ray{dvec3(0), dvec3(0, 1, 0)};
    SurfaceHit wall = parts.hit(ray.org, ray.dir);
    explicit ToTheWall(Parts& p, float surrounding = kL) : parts(p) { p.tracer.value = Spectrum(surrounding); }

    double along(PathState::Kind kind, uint64_t seed) {
        PathState state;
        state.kind = kind;
        PathContext ctx = parts.context(seed);
        HomogeneousMedium h = parts.media.homogeneousAlong(ray, &wall, state);
        return parts.transport.along(ray, wall, h, state, ctx, nullptr)[0];
    }
};

}  // namespace

// Beer–Lambert, in closed form, for the primary ray and for sampled ones alike (float precision, 1e-6).
TEST(MediaTransport, AbsorbingMediumDimsTheWallByBeerLambert) {
    Parts parts(kWall, medium(0));
    ToTheWall ray(parts);
    for (auto kind : {PathState::Kind::Primary, PathState::Kind::Sampled})
        EXPECT_NEAR(ray.along(kind, 1), kL * std::exp(-kSigma * kD), 1e-6 * kL);
    EXPECT_EQ(parts.tracer.surfaceRays.size(), 2u);
    EXPECT_TRUE(parts.tracer.sampledRays.empty());
}

// The primary ray's in-scattering point is forced into the medium with density ∝ σ e^{−σt}, so its weight
// T σ_s / density is a(1 − e^{−σd}) whatever the point: exact (1e-5), however many points -ms asks for
// (Radiance's rule: one per -ms of length, 1 to 16). Past -ab bounces, -av stands for the surrounding.
TEST(MediaTransport, PrimaryRayInAScatteringMediumGetsTheWallAndTheInScatteredLight) {
    for (auto [ms, points] : {std::pair{0.0, 1u}, {0.25, 8u}, {0.01, 16u}}) {
        RenderSettings s = medium(0.6);
        s.mediumSampling = ms;
        Parts parts(kWall, s);
        ToTheWall ray(parts);
        EXPECT_NEAR(ray.along(PathState::Kind::Primary, 1), furnace(0.6), 1e-5 * kL) << ms;
        ASSERT_EQ(parts.tracer.sampledRays.size(), points) << ms;
        const AskedRay& scattered = parts.tracer.sampledRays[0];
        EXPECT_EQ(scattered.state.ambientLevel, 1);
        EXPECT_GT(scattered.ray.org.y, 0);
        EXPECT_LT(scattered.ray.org.y, kD);
    }
    RenderSettings s = medium(0.6, 0);
    s.ambientValue = Spectrum(kL);
    Parts parts(kWall, s);
    EXPECT_NEAR(ToTheWall(parts).along(PathState::Kind::Primary, 1), furnace(0.6), 1e-5 * kL);
    EXPECT_TRUE(parts.tracer.sampledRays.empty());
}

// A sampled ray takes delta tracking's first collision (scattering a of the surrounding, by one drawn ray
// that leaves out the sources: there are none here, and next-event estimation at a point of its own has
// nothing to find) or, with probability e^{−σd}, the wall: unbiased. Mean of 4000 rays within 4 standard
// errors, and the fraction reaching the wall within 4 binomial standard deviations. Past -ab bounces with
// nothing beyond them (-al+), no collision adds light: no tracking, the wall by its exact e^{−σd} (1e-5).
TEST(MediaTransport, SampledRayTakesACollisionOrTheWallWithoutBias) {
    Parts parts(kWall, medium(0.6));
    ToTheWall ray(parts);
    Mean value;
    for (uint64_t seed = 0; seed < 4000; ++seed) value.add(ray.along(PathState::Kind::Sampled, seed));
    EXPECT_NEAR(value.value(), furnace(0.6), 4 * value.standardError());
    double p = std::exp(-kSigma * kD), reached = parts.tracer.surfaceRays.size() / 4000.0;
    EXPECT_NEAR(reached, p, 4 * std::sqrt(p * (1 - p) / 4000));
    EXPECT_EQ(parts.tracer.surfaceRays.size() + parts.tracer.rays.size(), 4000u);
    for (const AskedRay& r : parts.tracer.rays) EXPECT_EQ(r.state.kind, PathState::Kind::Sampled);

    RenderSettings limited = medium(0.6, 0);
    limited.ambientLimit = true;
    Parts past(kWall, limited);
    ToTheWall last(past);
    EXPECT_NEAR(last.along(PathState::Kind::Sampled, 1), kL * std::exp(-kSigma * kD), 1e-5 * kL);
    EXPECT_TRUE(past.tracer.rays.empty());
    EXPECT_EQ(past.tracer.surfaceRays.size(), 1u);
}

// A lamp beside the ray, and nothing else lit: a sampled ray takes the lamp's light scattered along it at a
// point drawn toward the lamp, as a primary ray does, so both estimate the same single scattering (means of
// 4000 rays within 4 standard errors of their difference), and the sampled ray's spread is within twice the
// primary's (delta tracking's collision would take the lamp's 1/r² wherever it falls, a heavy tail).
TEST(MediaTransport, SampledRayTakesALampsLightAtAPointDrawnTowardIt) {
    Parts parts(kWall + kLamp, medium(0.6, 0));
    ToTheWall ray(parts, 0);
    Mean primary, sampled;
    for (uint64_t seed = 0; seed < 4000; ++seed) {
        primary.add(ray.along(PathState::Kind::Primary, seed));
        sampled.add(ray.along(PathState::Kind::Sampled, seed + 10000));
    }
    double se = std::hypot(primary.standardError(), sampled.standardError());
    EXPECT_GT(primary.value(), 0);
    EXPECT_NEAR(sampled.value(), primary.value(), 4 * se);
    EXPECT_LT(sampled.standardError(), 2 * primary.standardError());
}

// A lamp beside the ray, and nothing else lit: the medium sends some of its light along the ray (next-event
// estimation at the in-scattering points), in proportion to its scattering coefficient σ a at a given σ:
// twice the albedo, twice the light, draw for draw (the draws depend on σ only: 1e-5); none without scattering.
TEST(MediaTransport, InScatteredLightOfALampGrowsWithTheAlbedo) {
    Parts once(kWall + kLamp, medium(0.3, 0)), twice(kWall + kLamp, medium(0.6, 0)), none(kWall + kLamp, medium(0, 0));
    for (uint64_t seed : {1, 2, 3}) {
        double light = ToTheWall(once, 0).along(PathState::Kind::Primary, seed);
        EXPECT_GT(light, 0);
        EXPECT_NEAR(ToTheWall(twice, 0).along(PathState::Kind::Primary, seed), 2 * light, 1e-5 * light);
        EXPECT_EQ(ToTheWall(none, 0).along(PathState::Kind::Primary, seed), 0);
    }
}
