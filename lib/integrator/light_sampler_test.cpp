// Next-event estimation against closed forms: a sphere lamp's light at a surface point and at a medium
// point, by one routine (sampleLd) that only the Scatterer tells apart; and the multiple-importance weight a
// drawn ray that meets the lamp takes.
#include "integrator/light_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_forms.h"
#include "integrator/testing.h"

using namespace brume;
using namespace brume::integrator_testing;
using std::numbers::pi;

namespace {

// A sphere lamp (L = 100, r = .5) 2 m above the floor's plane; the point lies off to the side, the lamp
// wholly above its horizon.
const std::string kLamp = "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 2 0.5\n";
const std::string kBlocker = "void plastic black 0 0 5 0 0 0 0 0\n"
                             "black polygon shade 0 0 12 -3 -3 1 3 -3 1 3 3 1 -3 3 1\n";
const dvec3 kCenter(0, 0, 2), kPoint(0.8, 0, 0), kUp(0, 0, 1);
constexpr double kL = 100, kRadius = 0.5, kRho = 0.6;

// The lamp's solid angle seen from the point: 2π(1 − cos α), sin α = r/d.
double solidAngle() {
    double sinAlpha = kRadius / glm::length(kCenter - kPoint);
    return 2 * pi * (1 - std::sqrt(1 - sinAlpha * sinAlpha));
}

// The same call at either kind of point.
double direct(Parts& parts, const Scatterer& at, const PathState& state, uint64_t seed) {
    PathContext ctx = parts.context(seed);
    return parts.lights.sampleLd(at, SurfaceId{}, state, ctx)[0];
}

struct Floor {
    Shading sh = flatHit(kPoint, kUp, -kUp);
    Lobes lobes;
    Floor() { lobes.diffuse = Spectrum(float(kRho)); }
    Scatterer scatterer() const { return Scatterer(sh, lobes); }
};

PathState atDepth(int depth) {
    PathState s;
    s.depth = depth;
    return s;
}

}  // namespace

// Where a primary ray lands (depth 0) the Lambertian part is the closed form (ρ/π) L E, E = π sin²α cos θ per
// unit radiance for a sphere wholly in view: exact (float precision, 1e-6).
TEST(LightSampler, LambertianSurfaceAtThePrimaryHitTakesTheClosedForm) {
    Parts parts(kLamp);
    Floor floor;
    double expected = kRho / pi * test::sphereIrradiance(kL, kRadius, kCenter, kPoint, kUp);
    for (uint64_t seed : {1, 2, 3}) EXPECT_NEAR(direct(parts, floor.scatterer(), atDepth(0), seed), expected, 1e-6 * expected);
}

// Deeper in a path the closed form gives way to shadow rays drawn uniformly over the lamp's cone: the cosine
// varies over it, so the estimate is noisy but unbiased. Mean of 400 estimates within 4 standard errors.
TEST(LightSampler, LambertianSurfaceDeeperInAPathIsSampledWithoutBias) {
    Parts parts(kLamp);
    Floor floor;
    double expected = kRho / pi * test::sphereIrradiance(kL, kRadius, kCenter, kPoint, kUp);
    Mean estimate;
    for (uint64_t seed = 0; seed < 400; ++seed) estimate.add(direct(parts, floor.scatterer(), atDepth(1), seed));
    EXPECT_GT(estimate.standardError(), 0);  // sampled indeed
    EXPECT_NEAR(estimate.value(), expected, 4 * estimate.standardError() + 1e-6 * expected);
}

// At a medium point, an isotropic phase mixture of coefficient 1 scatters L Ω/(4π) toward the ray; every
// shadow ray draws a direction in the cone with density 1/Ω, so each estimate is exact (1e-6).
TEST(LightSampler, IsotropicMediumPointScattersLTimesTheSolidAngleOver4Pi) {
    Parts parts(kLamp);
    PhaseMixture isotropic;
    isotropic.add(Spectrum(1.f), 0);
    Scatterer at(kPoint, glm::normalize(dvec3(1, 1, 0)), isotropic, false);
    double expected = kL * solidAngle() / (4 * pi);
    for (int depth : {0, 1})
        for (uint64_t seed : {1, 2}) EXPECT_NEAR(direct(parts, at, atDepth(depth), seed), expected, 1e-6 * expected);
}

// An opaque sheet between the point and the lamp: no light, at a surface (closed form or sampled) or in a
// medium. Exactly 0: the closed form is not kept where every shadow ray is blocked.
TEST(LightSampler, ABlockerBetweenPointAndLampLeavesNoLight) {
    Parts parts(kLamp + kBlocker);
    Floor floor;
    PhaseMixture isotropic;
    isotropic.add(Spectrum(1.f), 0);
    Scatterer medium(kPoint, dvec3(1, 0, 0), isotropic, false);
    for (int depth : {0, 1}) {
        EXPECT_EQ(direct(parts, floor.scatterer(), atDepth(depth), 4), 0.0) << depth;
        EXPECT_EQ(direct(parts, medium, atDepth(depth), 4), 0.0) << depth;
    }
}

// A ray drawn from a lobe with density p that meets the lamp keeps the power heuristic's share of its light
// against next-event estimation's density there: 1/Ω per shadow ray times the shadow rays it took at the
// ray's origin (as many as the drawing point's depth and weight gave it). Between 0 and 1, growing with p;
// smaller from a primary hit, which took more shadow rays.
TEST(LightSampler, MisWeightIsThePowerHeuristicAgainstTheShadowRaysAtTheOrigin) {
    Parts parts(kLamp);
    const Light& lamp = parts.scene.render.lights()[0];
    Ray ray{kPoint, glm::normalize(kCenter - kPoint)};
    SurfaceHit onLamp = parts.hit(ray.org, ray.dir);
    auto weight = [&](double pdf, int depth) {
        PathState child;
        parts.lights.drawnFrom(child, kPoint, pdf, atDepth(depth));
        EXPECT_EQ(child.kind, PathState::Kind::Sampled);
        return parts.lights.misWeight(lamp, child, ray, &onLamp);
    };
    double shadowRays = lamp.sampleCount(kPoint, parts.settings.sourceSubdivision, 1);
    double lightDensity = shadowRays / solidAngle();
    double previous = 0;
    for (double pdf : {0.01, 1.0, 30.0, 1e4}) {
        double w = weight(pdf, 1);
        EXPECT_NEAR(w, pdf * pdf / (pdf * pdf + lightDensity * lightDensity), 1e-9) << pdf;
        EXPECT_GE(w, previous);
        EXPECT_LE(w, 1.0);
        previous = w;
        EXPECT_LT(weight(pdf, 0), w) << pdf;
    }
}
