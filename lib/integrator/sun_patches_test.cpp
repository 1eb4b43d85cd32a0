// Sampling the sun's patches: points landed across the sunbeam through the windows against the density the
// integrator weighs them by (chi-square, as directions from a point that sees them all), and the light the
// patches send, which must be what cosine-distributed rays alone find (unbiased) with less noise.
#include "integrator/sun_patches.h"

#include <gtest/gtest.h>

#include "integrator/testing.h"
#include "sampling/testing.h"

using namespace brume;
using namespace brume::integrator_testing;

namespace {

// The sun south-east and high: its beam enters both panes and lands on the floor and the west wall.
const std::string kSun = "void light solar 0 0 3 2e5 2e5 2e5\nsolar source sun 0 0 4 .6 -1 .8 0.5\n";

int sunLight(const Parts& parts) {
    const auto& lights = parts.scene.render.lights();
    for (size_t i = 0; i < lights.size(); ++i)
        if (lights[i].isDistant() && lights[i].emitter().kind == Emitter::Kind::Light) return int(i);
    ADD_FAILURE() << "no sun";
    return -1;
}

}  // namespace

TEST(SunPatches, OnlyWithASunAndWindows) {
    EXPECT_FALSE(Parts(daylitRoom(0.5), daylitPathTracing(1, 64, true)).patches.active()) << "no sun";
    EXPECT_TRUE(Parts(daylitRoom(0.5, kSun), daylitPathTracing(1, 64, true)).patches.active());
    EXPECT_FALSE(Parts(daylitRoom(0.5, kSun), daylitPathTracing(1, 64, false)).patches.active()) << "-aP-";
}

// Seen from under the ceiling, every point the beam lands on is in view and on one line of sight only: the
// directions to the landed points follow the area density, carried to solid angle by d²/|cos|.
TEST(SunPatches, LandedPointsFollowTheirDensity) {
    Parts parts(daylitRoom(0.5, kSun), daylitPathTracing(1, 64, true));
    int sun = sunLight(parts);
    const dvec3 eye(2, 2.5, 2.9);
    auto draw = [&](double u, double v) -> std::optional<dvec3> {
        auto landed = parts.patches.land(sun, u, v);
        if (!landed) return std::nullopt;
        return glm::normalize(landed->point - eye);
    };
    auto density = [&](const dvec3& d) {
        auto seen = parts.scene.render.geometry().intersect(Ray{eye, d});
        if (!seen) return 0.0;
        double cosine = std::abs(glm::dot(seen->normal, d));
        return parts.patches.areaDensity(sun, seen->point, seen->surface, seen->normal) * seen->t * seen->t / cosine;
    };
    sampling::testing::expectSamplesFollowDensity(draw, density, {.draws = 400'000, .rings = 40, .sectors = 80});
}

// With pale walls the patches light the room. Aiming at them (and at the sky) changes the noise, not the
// answer: as for the portals, the mean of many runs by rays alone and of fewer aimed ones agree within 4
// standard errors of their difference (about 1% here).
TEST(SunPatches, AimingAtPatchesKeepsTheAnswerAndLowersTheNoise) {
    struct Case {
        int bounces;
        dvec3 p, n;
    };
    for (const Case& c : {Case{1, dvec3(1, 3.5, 2.9), dvec3(0, 0, -1)}, Case{3, dvec3(3.5, 3.5, 0.8), dvec3(0, 0, 1)},
                          Case{3, dvec3(0.1, 1, 1.5), dvec3(1, 0, 0)}}) {
        Spread rays = irradianceRuns(daylitRoom(0.6, kSun), daylitPathTracing(c.bounces, 256, false), c.p, c.n, 3000);
        Spread aimed = irradianceRuns(daylitRoom(0.6, kSun), daylitPathTracing(c.bounces, 256, true), c.p, c.n, 100);
        EXPECT_NEAR(aimed.mean, rays.mean, 4 * std::hypot(rays.standardError, aimed.standardError))
            << c.p.x << " " << c.p.y << " " << c.p.z;
        EXPECT_LT(aimed.deviation, 0.5 * rays.deviation) << c.p.x << " " << c.p.y << " " << c.p.z;
    }
}
