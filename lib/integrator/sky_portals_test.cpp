// Sampling the sky through windows: which glazing counts as a portal, the directions aimed at the portals
// against the density the integrator weighs them by (chi-square), and the light through them, which must be
// what cosine-distributed rays alone find (unbiased) with less noise.
#include "integrator/sky_portals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrator/integrator.h"
#include "integrator/testing.h"
#include "sampling/testing.h"

using namespace brume;
using namespace brume::integrator_testing;
using std::numbers::pi;

TEST(SkyPortals, WindowsTowardTheSkyArePortalsAndGlassWithinIsNot) {
    // A glass partition in a closed room beside (x 10 to 12) leads nowhere but to walls.
    std::string closedRoom =
        "wall polygon floor2 0 0 12 10 0 0 12 0 0 12 2 0 10 2 0\n"
        "wall polygon ceiling2 0 0 12 10 0 2 10 2 2 12 2 2 12 0 2\n"
        "wall polygon north2 0 0 12 10 2 0 12 2 0 12 2 2 10 2 2\n"
        "wall polygon south2 0 0 12 10 0 0 10 0 2 12 0 2 12 0 0\n"
        "wall polygon west2 0 0 12 10 0 0 10 2 0 10 2 2 10 0 2\n"
        "wall polygon east2 0 0 12 12 0 0 12 0 2 12 2 2 12 2 0\n"
        "pane polygon partition 0 0 12 11 .5 .5 11 .5 1.5 11 1.5 1.5 11 1.5 .5\n";
    test::TestScene scene(daylitRoom(0.5, closedRoom));
    ASSERT_EQ(scene.render.portals().size(), 2u);
    test::TestScene night(daylitRoom(0.5).substr(daylitRoom(0.5).find("void glass")));
    EXPECT_TRUE(night.render.portals().empty()) << "no sky: nothing to aim at";
}

// The directions aimed at both portals (a rectangle, and a triangle sampled by its spherical triangle) follow
// the density the integrator weighs them by, from points that see both, one, or one partly below their horizon.
TEST(SkyPortals, AimedDirectionsFollowTheirDensity) {
    Parts parts(daylitRoom(0.5), daylitPathTracing(1, 64, true));
    for (auto [p, n] : {std::pair{dvec3(2, 2, 0.8), dvec3(0, 0, 1)}, std::pair{dvec3(1, 3, 1.5), dvec3(1, 0, 0)},
                        std::pair{dvec3(3.5, 1.5, 2.9), glm::normalize(dvec3(0.2, -1, -0.5))}}) {
        auto draw = [&](double u, double v) { return parts.portals.aim(p, n, u, v, parts.scratch); };
        auto density = [&](const dvec3& d) { return parts.portals.density(p, n, d, parts.scratch); };
        sampling::testing::expectSamplesFollowDensity(draw, density, {.draws = 400'000, .rings = 40, .sectors = 80});
    }
}

// With every wall black, only the sky and ground through the panes light a sensor; with pale walls, their
// light comes back by several bounces. Aiming at the portals changes the noise, not the answer: the mean of
// many runs by rays alone (the estimator Radiance's numbers check elsewhere) and of fewer aimed ones agree
// within 4 standard errors of their difference (a false alarm once in 15,000), which is about 1% of the
// answer here: a portal sample weighted 3% too much would fail.
TEST(SkyPortals, AimingAtWindowsKeepsTheAnswerAndLowersTheNoise) {
    struct Case {
        double rho;
        int bounces;
        dvec3 p, n;
    };
    for (const Case& c : {Case{0, 1, dvec3(2, 2.5, 0.8), dvec3(0, 0, 1)},
                          Case{0, 1, dvec3(2.5, 1.5, 1.2), glm::normalize(dvec3(1, -1, 0))},
                          Case{0.6, 4, dvec3(1, 3.5, 0.8), dvec3(0, 0, 1)}}) {
        Spread rays = irradianceRuns(daylitRoom(c.rho), daylitPathTracing(c.bounces, 256, false), c.p, c.n, 3000);
        Spread aimed = irradianceRuns(daylitRoom(c.rho), daylitPathTracing(c.bounces, 256, true), c.p, c.n, 100);
        double tolerance = 4 * std::hypot(rays.standardError, aimed.standardError);
        EXPECT_NEAR(aimed.mean, rays.mean, tolerance) << "walls " << c.rho;
        // Far more than the 10% or so by which 100 runs misjudge a deviation.
        EXPECT_LT(aimed.deviation, 0.5 * rays.deviation) << "walls " << c.rho;
    }
}
