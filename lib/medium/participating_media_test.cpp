// Flames as light sources: the directions ParticipatingMedia draws toward them follow the density per steradian
// it reports (chi-square, sampling/testing.h), which weighs them against rays drawn from lobes and divides their
// light: from outside the flames' box (points drawn in the emission cells alone) and from inside it (half the
// directions uniform over the sphere).
#include "medium/participating_media.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <sstream>

#include "medium/testing.h"
#include "ray_path_dir.h"
#include "sampling/testing.h"
#include "scene/reader.h"

namespace brume {
namespace {

using namespace medium::testing;

// A flame 1 m across: soot 1 in voxels 0..9 of 0.1 m, at 1500 K, and cooler (900 K) in its upper half.
ParticipatingMedia flame(const RayPathDir& dir) {
    auto density = boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f, 0.1);
    auto temperature = boxGrid({-1, -1, -1}, {10, 10, 10}, 1500.0f, 0.1);
    temperature->tree().fill(openvdb::CoordBBox({-1, -1, 5}, {10, 10, 10}), 900.0f, true);
    density->setName("density"), temperature->setName("temperature");
    openvdb::io::File((dir.path() / "flame.vdb").string()).write({density, temperature});
    Scene scene;
    std::istringstream in("void smoke f 2 temperature=temperature flame.vdb 0 3 2 2 2\n");
    readSceneText(scene, in, "t.rad");
    std::vector<SmokeVolume> volumes;
    volumes.emplace_back(readSmoke(scene.objects.at(0)), 0);
    return ParticipatingMedia(std::move(volumes));
}

void expectDirectionsFollowTheirDensity(const ParticipatingMedia& media, const dvec3& eye,
                                        const sampling::testing::DirectionOptions& options) {
    Random extra(7);
    auto draw = [&](double u, double v) { return media.sampleFlameDirection(eye, u, v, extra.uniform(), extra.uniform()); };
    sampling::testing::expectSamplesFollowDensity(draw, [&](const dvec3& d) { return media.flameDirectionDensity(eye, d); },
                                                  options);
}

TEST(ParticipatingMedia, FlameDirectionsFromOutsideFollowTheirDensity) {
    RayPathDir dir;
    ParticipatingMedia media = flame(dir);
    ASSERT_TRUE(media.hasFlames());
    const dvec3 eye(2.2, -1.3, 0.9);
    std::vector<dvec3> corners;
    for (int i = 0; i < 8; ++i) corners.push_back(dvec3(-0.1 + 1.1 * (i & 1), -0.1 + 1.1 * ((i >> 1) & 1), -0.1 + 1.1 * (i >> 2)));
    expectDirectionsFollowTheirDensity(media, eye,
                                       sampling::testing::capAround(eye, corners, {.draws = 400'000, .rings = 40, .sectors = 80}));
}

TEST(ParticipatingMedia, FlameDirectionsFromInsideFollowTheirDensity) {
    RayPathDir dir;
    ParticipatingMedia media = flame(dir);
    const dvec3 eye(0.42, 0.37, 0.61);  // in the cooler half, near the hot one
    expectDirectionsFollowTheirDensity(media, eye, {.draws = 400'000, .rings = 40, .sectors = 80});
    // The sphere's half floors the density everywhere.
    for (const dvec3& d : {dvec3(1, 0, 0), dvec3(0, 0, -1), glm::normalize(dvec3(-1, 2, 3))})
        EXPECT_GE(media.flameDirectionDensity(eye, d), 0.5 / (4 * std::numbers::pi));
}

// The flames' light scattered once within their box is drawn where their smoke's first collision falls: in even
// smoke (the flame's interior, K 2 /m) the density σ e^{−σ(t − a)} / (1 − e^{−σ(b − a)}) on [a, b], which the draws
// follow and each draw's density reports.
TEST(ParticipatingMedia, SmokeCollisionsFollowTheDensityTheyReport) {
    RayPathDir dir;
    ParticipatingMedia media = flame(dir);
    const Ray ray(dvec3(-1, 0.45, 0.25), dvec3(1, 0, 0));
    const double a = 1.2, b = 1.8, sigma = 2;  // x 0.2-0.8: inside the box, away from its ramping edges
    auto exact = [&](double t) { return sigma * std::exp(-sigma * (t - a)) / -std::expm1(-sigma * (b - a)); };
    auto draw = [&](double u) -> std::optional<double> {
        auto d = media.smokeCollision(ray, a, b, u);
        if (!d) return std::nullopt;
        EXPECT_NEAR(d->second, exact(d->first), 1e-6 * exact(d->first));
        return d->first;
    };
    sampling::testing::expectSamplesFollowDensity(draw, exact, {.lo = a, .hi = b, .bins = 60, .draws = 200'000});
    EXPECT_FALSE(media.smokeCollision(Ray(dvec3(-1, 5, 5), dvec3(1, 0, 0)), 0, 3, 0.5));  // no smoke there
}

}  // namespace
}  // namespace brume
