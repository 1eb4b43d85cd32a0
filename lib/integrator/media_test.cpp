// The media light crosses: the smoke at each instant (key frames in time, or one grid for all), the global
// medium and the mists a path is inside.
#include "integrator/media.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "integrator/testing.h"
#include "medium/testing.h"
#include "ray_path_dir.h"

using namespace brume;
using namespace brume::integrator_testing;

namespace {

// Smoke of even density over [0, 9.9]³ (voxels of .1), extinction .1 per unit density.
void writeBox(const RayPathDir& dir, const std::string& file, float density) {
    medium::testing::writeGrid(dir.path() / file, medium::testing::boxGrid({0, 0, 0}, {99, 99, 99}, density, 0.1));
}

// 7 m through the box.
const Ray kThrough{dvec3(5, 1, 5), dvec3(0, 1, 0)};
constexpr double kLength = 7;

// Beer–Lambert through the smoke of instant `time` (ratio tracking takes even smoke in closed form).
double transmittance(Parts& parts, double time) {
    Random rng(1);
    HomogeneousMedium clear;
    return parts.media.smokeAt(time).transmittance(kThrough, 0, kLength, clear)[0];
}

RenderSettings at(double time) {
    RenderSettings s = test::fixedSeed();
    s.time = time;
    return s;
}

// A mist sphere of radius 1 about the origin (σ .2, albedo .5, g .3) in a global medium (σ .1, albedo .9).
const std::string kFog = "void mist fog 0 0 7 .2 .2 .2 .5 .5 .5 .3\nfog sphere blob 0 0 4 0 0 0 1\n";

RenderSettings globalMedium() {
    RenderSettings s = test::fixedSeed();
    s.medium.extinction = Spectrum(0.1f);
    s.medium.albedo = Spectrum(0.9f);
    s.medium.g = -0.2;
    return s;
}

}  // namespace

// Key frames of density 1 (t = 10 s) and 3 (t = 20 s): each instant has its own smoke, built where it is first
// asked for (no instant needs preparing), whose transmittance is e^{−.1 ρ 7} (1e-5: exact for even smoke),
// 2 halfway; forgetting the instants before one rebuilds theirs alike when asked again; an instant outside the
// key frames is an Error naming them.
TEST(IntegratorMedia, EachInstantHasItsOwnSmoke) {
    RayPathDir dir;
    writeBox(dir, "one.vdb", 1.0f);
    writeBox(dir, "three.vdb", 3.0f);
    Parts parts("void smoke s 4 20 three.vdb 10 one.vdb 0 3 .1 .1 .1\n", at(10));
    EXPECT_NEAR(transmittance(parts, 20), std::exp(-2.1), 1e-5);
    EXPECT_NEAR(transmittance(parts, 10), std::exp(-0.7), 1e-5);
    EXPECT_NEAR(transmittance(parts, 15), std::exp(-1.4), 1e-5);
    parts.instants.forgetBefore(20);
    EXPECT_NEAR(transmittance(parts, 10), std::exp(-0.7), 1e-5);
    EXPECT_EQ(parts.instants.last(), 20);
    try {
        parts.media.smokeAt(25);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("outside its 2 key frames (10 to 20 s"), std::string::npos) << e.what();
    }
}

// Threads that ask for instants at once each get the one smoke of their instant.
TEST(IntegratorMedia, ThreadsAskingAtOnceShareOneSmokePerInstant) {
    RayPathDir dir;
    writeBox(dir, "one.vdb", 1.0f);
    writeBox(dir, "three.vdb", 3.0f);
    Parts parts("void smoke s 4 20 three.vdb 10 one.vdb 0 3 .1 .1 .1\n", at(10));
    std::vector<const ParticipatingMedia*> seen(8);
    std::vector<std::thread> threads;
    for (size_t i = 0; i < seen.size(); ++i)
        threads.emplace_back([&, i] { seen[i] = &parts.media.smokeAt(10 + 5 * double(i % 2)); });
    for (std::thread& t : threads) t.join();
    for (size_t i = 2; i < seen.size(); ++i) EXPECT_EQ(seen[i], seen[i % 2]) << i;
    EXPECT_NE(seen[0], seen[1]);
}

// Smoke of one grid does not change in time: the smoke built once serves every instant, and is kept.
TEST(IntegratorMedia, StaticSmokeServesEveryInstant) {
    RayPathDir dir;
    writeBox(dir, "one.vdb", 1.0f);
    Parts parts("void smoke s 1 one.vdb 0 3 .1 .1 .1\n", at(0));
    parts.instants.forgetBefore(5);
    for (double time : {0.0, 5.0, 123.0}) EXPECT_NEAR(transmittance(parts, time), std::exp(-0.7), 1e-5) << time;
    EXPECT_TRUE(parts.media.present());
}

// Inside a mist the medium is the global one with the mist's extinction added and its albedo and g; a ray
// leaving the mist through its boundary, from a start not known to be inside (the state names no mist), was in
// it all the way. Exact.
TEST(IntegratorMedia, HomogeneousAlongAddsTheMistsThePathIsIn) {
    Parts parts(kFog, globalMedium());
    Ray outward{dvec3(0), dvec3(1, 0, 0)};
    SurfaceHit boundary = parts.hit(outward.org, outward.dir);
    PathState outside, inside;
    inside.mists.enter(parts.object("fog"));
    HomogeneousMedium global = parts.media.homogeneousAlong(outward, nullptr, outside);
    EXPECT_FLOAT_EQ(global.extinction[0], 0.1f);
    EXPECT_FLOAT_EQ(global.albedo[0], 0.9f);
    EXPECT_DOUBLE_EQ(global.g, -0.2);
    for (const PathState& state : {inside, outside}) {
        HomogeneousMedium h = parts.media.homogeneousAlong(outward, &boundary, state);
        EXPECT_FLOAT_EQ(h.extinction[0], 0.3f);
        EXPECT_FLOAT_EQ(h.albedo[0], 0.5f);
        EXPECT_DOUBLE_EQ(h.g, 0.3);
    }
    // Entering it from outside, the ray was not in it before the boundary.
    Ray inward{dvec3(-3, 0, 0), dvec3(1, 0, 0)};
    SurfaceHit entry = parts.hit(inward.org, inward.dir);
    EXPECT_FLOAT_EQ(parts.media.homogeneousAlong(inward, &entry, outside).extinction[0], 0.1f);
}

// Where nothing absorbs or scatters, rays skip the media altogether; a mist alone, or the global medium alone,
// makes them ask. Shadow rays are attenuated inside a mist, not outside it in a clear scene.
TEST(IntegratorMedia, MediaArePresentOnlyWhereSomethingAbsorbs) {
    const std::string ball = "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere ball 0 0 4 0 0 0 1\n";
    Parts clear(ball), global(ball, globalMedium());
    EXPECT_FALSE(clear.media.present());
    EXPECT_TRUE(global.media.present());
    Parts fog(kFog);
    EXPECT_TRUE(fog.media.present());
    PathState outside, inside;
    inside.mists.enter(fog.object("fog"));
    Ray shadow{dvec3(0), dvec3(0, 0, 1)};
    EXPECT_TRUE(fog.media.attenuates(shadow, 0.5, inside, fog.media.smokeAt(0)));
    EXPECT_FALSE(fog.media.attenuates(shadow, 0.5, outside, fog.media.smokeAt(0)));
    Random rng;
    EXPECT_NEAR(fog.media.clearTransmittance(shadow, 0.5, inside, fog.media.smokeAt(0))[0], std::exp(-0.1), 1e-6);
}
