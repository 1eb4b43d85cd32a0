// A surface's lobes in a uniform surrounding of radiance L (a tracer that answers every ray with L) and no
// sources: each lobe returns what it reflects of L, by its rays.
#include "integrator/surface_scattering.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/testing.h"
#include "material/ward.h"

using namespace brume;
using namespace brume::integrator_testing;

namespace {

// A floor, whose surface the rays leave; no sources.
const std::string kFloor = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
const dvec3 kUp(0, 0, 1);
constexpr float kL = 2, kRho = 0.6f;

RenderSettings bounces(int ab, double aa = 0, int ad = 256) {
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = ab, s.ambientAccuracy = aa, s.ambientDivisions = ad;
    return s;
}

Lobes lambertian(float rho) {
    Lobes lobes;
    lobes.diffuse = lobes.ambient = Spectrum(rho);
    return lobes;
}

// The floor hit 40° off its normal, shaded at a state of `ambientLevel` diffuse bounces.
struct FloorHit {
    Parts& parts;
    Shading sh = flatHit(dvec3(0.3, 0.2, 0), kUp, glm::normalize(dvec3(0.64, 0, -0.77)));
    SurfaceId surface;
    explicit FloorHit(Parts& p) : parts(p), surface(p.hit(dvec3(0.3, 0.2, 1), -kUp).surface) {}

    double shade(const Lobes& lobes, uint64_t seed, int ambientLevel = 0) {
        PathState state;
        state.ambientLevel = ambientLevel;
        PathContext ctx = parts.context(seed);
        return parts.surfaces.shade(sh, lobes, surface, state, ctx, nullptr)[0];
    }
};

}  // namespace

// -ab 1 -aa 0: the Lambertian surface sends -ad cosine-distributed paths, each returning L, so its value is
// ρL exactly (float precision, 1e-6). Their mean cosine is 2/3 (within 4 standard deviations of 256 independent
// draws': 0.06; uniform directions would give 1/2), and each is a sampled path one bounce deeper.
TEST(SurfaceScattering, LambertianSurfaceReflectsRhoTimesAUniformSurrounding) {
    Parts parts(kFloor, bounces(1));
    parts.tracer.value = Spectrum(kL);
    FloorHit floor(parts);
    EXPECT_NEAR(floor.shade(lambertian(kRho), 1), kRho * kL, 1e-6 * kL);
    ASSERT_EQ(parts.tracer.rays.size(), 256u);
    double meanCosine = 0;
    for (const AskedRay& r : parts.tracer.rays) {
        EXPECT_GT(glm::dot(r.ray.dir, kUp), 0);
        EXPECT_EQ(r.ray.leaving, floor.surface);
        EXPECT_EQ(r.state.kind, PathState::Kind::Sampled);
        EXPECT_EQ(r.state.ambientLevel, 1);
        meanCosine += glm::dot(r.ray.dir, kUp) / 256;
    }
    EXPECT_NEAR(meanCosine, 2.0 / 3, 4 * std::sqrt(1.0 / 18 / 256));
}

// Past -ab bounces (or with -ad 0), -av stands for the light of the bounces left: ρ·av, and no ray.
TEST(SurfaceScattering, PastTheBouncesTheAmbientValueStandsForTheRest) {
    for (int ad : {256, 0}) {
        RenderSettings s = bounces(1, 0, ad);
        s.ambientValue = Spectrum(0.5f);
        Parts parts(kFloor, s);
        FloorHit floor(parts);
        EXPECT_NEAR(floor.shade(lambertian(kRho), 1, ad ? 1 : 0), kRho * 0.5, 1e-7) << ad;
        EXPECT_TRUE(parts.tracer.rays.empty());
    }
}

// With the cache's settings and no -av, paths past -ab go on, one each, played by Russian roulette on the
// reflectance: ρL on average (within 4 standard errors of 4000 shadings).
TEST(SurfaceScattering, PastTheBouncesWithTheCacheOnePathGoesOnByRoulette) {
    Parts parts(kFloor, bounces(1, 0.1));
    parts.tracer.value = Spectrum(kL);
    FloorHit floor(parts);
    Mean value;
    for (uint64_t seed = 0; seed < 4000; ++seed) value.add(floor.shade(lambertian(kRho), seed, 1));
    EXPECT_LT(parts.tracer.rays.size(), 4000u);  // the roulette ended some
    EXPECT_NEAR(value.value(), kRho * kL, 4 * value.standardError());
}

// A sampled Ward lobe reflects, of a uniform surrounding, its directional albedo ∫ f cos θ dω times L: one
// drawn ray a shading, weighted f cos θ / pdf (none where the draw falls below the horizon). Mean of 4000
// shadings within 4 standard errors, of the albedo by quadrature (1e-4 on 512 × 1024 cells).
TEST(SurfaceScattering, SampledWardLobeReflectsItsDirectionalAlbedo) {
    Parts parts(kFloor);
    parts.tracer.value = Spectrum(kL);
    FloorHit floor(parts);
    Lobes lobes;
    lobes.glossy = Spectrum(0.5f);
    lobes.alpha2 = 0.04;
    lobes.sampleGlossy = true;
    dvec3 wo = -floor.sh.dir;
    double albedo = overDirections([&](const dvec3& l) { return wardBrdf(wo, l, kUp, 0.04) * l.z; }, kUp, 512);
    Mean value;
    for (uint64_t seed = 0; seed < 4000; ++seed) value.add(floor.shade(lobes, seed));
    EXPECT_NEAR(value.value(), 0.5 * albedo * kL, 4 * value.standardError() + 1e-4 * kL);
}

// Each specular lobe spawns exactly one ray, in its direction, bringing its coefficient times what that ray
// brings. The mirror's child is a reflection; the pane's is not.
TEST(SurfaceScattering, SpecularLobesSpawnOneRayEach) {
    Parts parts(kFloor);
    parts.tracer.value = Spectrum(kL);
    FloorHit floor(parts);
    Lobes lobes;
    dvec3 mirrored = floor.sh.dir - 2 * glm::dot(floor.sh.dir, kUp) * kUp;
    lobes.addDelta(2.0 * mirrored, Spectrum(0.3f), false);  // directions as materials give them: not unit
    lobes.addDelta(floor.sh.dir, Spectrum(0.5f), true);
    EXPECT_NEAR(floor.shade(lobes, 1), (0.3 + 0.5) * kL, 1e-6);
    ASSERT_EQ(parts.tracer.rays.size(), 2u);
    const AskedRay &reflected = parts.tracer.rays[0], &through = parts.tracer.rays[1];
    EXPECT_NEAR(glm::distance(reflected.ray.dir, mirrored), 0, 1e-12);
    EXPECT_NEAR(glm::distance(through.ray.dir, floor.sh.dir), 0, 1e-12);
    EXPECT_EQ(reflected.ray.org, floor.sh.point);
    EXPECT_EQ(reflected.state.kind, PathState::Kind::Specular);
    EXPECT_EQ(reflected.state.reflections, 1);
    EXPECT_EQ(through.state.reflections, 0);
}

// A sampled path going straight through a pane stays sampled: the sources it meets beyond were counted by
// next-event estimation at its origin (shadow rays cross the pane too), so their share goes on to the caller,
// times the pane's transmission. Any other specular child makes a path only rays find.
TEST(SurfaceScattering, StraightThroughASampledPathKeepsSharingSources) {
    Parts parts(kFloor);
    parts.tracer.share = Spectrum(4.f);
    FloorHit floor(parts);
    Lobes pane;
    pane.addDelta(floor.sh.dir, Spectrum(0.5f), true);
    for (PathState::Kind kind : {PathState::Kind::Sampled, PathState::Kind::Primary}) {
        PathState state;
        state.kind = kind;
        Spectrum share(0.f);
        PathContext ctx = parts.context(1);
        parts.surfaces.shade(floor.sh, pane, floor.surface, state, ctx, &share);
        bool stays = kind == PathState::Kind::Sampled;
        EXPECT_EQ(parts.tracer.rays.back().state.kind, stays ? kind : PathState::Kind::Specular);
        EXPECT_FLOAT_EQ(share[0], stays ? 0.5f * 4 : 0.f);
    }
}
