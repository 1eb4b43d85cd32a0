// The work of a run in passes: with the irradiance cache, items that miss records run again once the records
// are made, in an order the threads do not change; each frame's passes start afresh, and the records of one
// instant serve only that instant.
#include "render/sequence.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cmath>
#include <numbers>

#include "medium/testing.h"
#include "ray_path_dir.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;

namespace {

// A wide ground of reflectance .3 under a uniform sky of radiance 2 (a glow, which no shadow ray samples): a
// sensor facing down sees only the ground, of radiance ρL, so its irradiance is πρL, all of it reaching it
// in two diffuse bounces.
const char* kGround = "void glow skyglow 0 0 4 2 2 2 0\n"
                      "skyglow source sky 0 0 4 0 0 1 180\n"
                      "void plastic ground 0 0 5 .3 .3 .3 0 0\n"
                      "ground polygon floor 0 0 12 -500 -500 0 500 -500 0 500 500 0 -500 500 0\n";
const double kDown = std::numbers::pi * 0.3 * 2;

// A lamp over a floor by a wall: indirect light that varies from point to point, which records estimate with
// noise (so values depend on which records serve them).
const char* kRoom = "void light lamp 0 0 3 50 50 50\n"
                    "lamp sphere bulb 0 0 4 0 0 2.5 .2\n"
                    "void plastic white 0 0 5 .7 .7 .7 0 0\n"
                    "white polygon floor 0 0 12 -3 -3 0 3 -3 0 3 3 0 -3 3 0\n"
                    "white polygon wall 0 0 12 -3 3 0 3 3 0 3 3 3 -3 3 3\n";

RenderSettings settings(double aa, uint64_t seed = 0) {
    RenderSettings s = fixedSeed();
    s.seed = seed;
    s.ambientBounces = 2, s.ambientAccuracy = aa, s.ambientDivisions = 64;
    return s;
}

// Sensors facing down, in rows of 13 over the floor: each item's last value, and how often each ran.
struct Sensors {
    std::vector<double> values;
    std::vector<std::atomic<int>> runs;

    Sensors(Sequence& sequence, size_t count, double time = 0) : values(count), runs(count) {
        sequence.run(count, time, [&](size_t i, WorkItem& item) {
            ++runs[i];
            dvec3 p(0.43 * (i % 13) - 2.6, 0.37 * (i / 13) - 2.6, 1 + 0.01 * (i % 7));
            RayQuery q{p, dvec3(0, 0, -1), i};
            q.time = time;
            values[i] = sequence.integrator().irradiance(q, item).value[0];
        });
    }
    double mean() const {
        double sum = 0;
        for (double v : values) sum += v;
        return sum / double(values.size());
    }
    int runsInAll() const {
        int n = 0;
        for (const auto& r : runs) n += r;
        return n;
    }
};

}  // namespace

// -u-: the records are made in an order the items fix, not the threads, so the values are the same on one
// thread or two (another seed gives others: they do depend on the records' samples).
TEST(Sequence, SameValuesOnOneOrTwoThreadsWithTheCache) {
    TestScene t(kRoom);
    auto values = [&](int threads, uint64_t seed) {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
        Sequence sequence(t.scene, t.render, settings(0.1, seed));
        return Sensors(sequence, 169).values;
    };
    std::vector<double> one = values(1, 0);
    EXPECT_EQ(one, values(2, 0));
    EXPECT_NE(one, values(2, 1));
}

// An item whose lookups missed records runs again once they are made, and the value it keeps is its last
// one: a waiting miss counts 0 for the indirect light, all the light here, so a moot value would be 0. Each is
// πρL within float precision (1e-5): every record's strata see the uniform ground, every ground record's the
// uniform sky.
TEST(Sequence, ItemsThatMissRecordsRunAgainAndKeepTheirLastValue) {
    TestScene t(kGround);
    Sequence sequence(t.scene, t.render, settings(0.1));
    ASSERT_NE(sequence.cache(), nullptr);
    Sensors sensors(sequence, 12);
    int again = 0;
    for (size_t i = 0; i < sensors.values.size(); ++i) {
        again += sensors.runs[i] > 1;
        EXPECT_NEAR(sensors.values[i], kDown, 1e-5 * kDown) << i;
    }
    EXPECT_GT(again, 0);
}

// Without the cache (-aa 0) nothing is waited for: each item runs once, and its paths find πρL too (each
// meets the ground, then the sky).
TEST(Sequence, WithoutTheCacheEachItemRunsOnce) {
    TestScene t(kGround);
    Sequence sequence(t.scene, t.render, settings(0));
    EXPECT_EQ(sequence.cache(), nullptr);
    Sensors sensors(sequence, 12);
    for (size_t i = 0; i < sensors.values.size(); ++i) {
        EXPECT_EQ(sensors.runs[i], 1) << i;
        EXPECT_NEAR(sensors.values[i], kDown, 1e-5 * kDown) << i;
    }
}

namespace {

// Absorbing smoke (key frames of density 1 at t = 10 s and 3 at t = 20 s, written into `dir`) over a floor
// lit by a lamp above it.
std::string smokeInTime(const RayPathDir& dir) {
    using namespace medium::testing;
    writeGrid(dir.path() / "one.vdb", boxGrid({0, 0, 0}, {19, 19, 19}, 1.0f, 0.1));
    writeGrid(dir.path() / "three.vdb", boxGrid({0, 0, 0}, {19, 19, 19}, 3.0f, 0.1));
    return "void light lamp 0 0 3 50 50 50\n"
           "lamp sphere bulb 0 0 4 1 1 3 .2\n"
           "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
           "grey polygon floor 0 0 12 -2 -2 0 4 -2 0 4 4 0 -2 4 0\n"
           "grey polygon wall 0 0 12 -2 4 0 4 4 0 4 4 3 -2 4 3\n"
           "void smoke s 4 20 three.vdb 10 one.vdb 0 3 .5 .5 .5\n";
}

// That scene, seen from the side with the cache on.
struct SmokeInTime {
    RayPathDir dir;
    TestScene t{smokeInTime(dir)};

    std::vector<float> frame(Sequence& sequence, double time) const {
        View v;
        v.vp = {1, -3, 2};
        v.vd = {0, 1, -0.4};
        PictureSettings p;
        p.xres = p.yres = 8;
        return sequence.render(SequenceFrame{v, 0, time}, p, nullptr).picture.pixels;
    }
    // -at 0: each record serves its own instant alone.
    Sequence fresh() const {
        RenderSettings s = settings(0.1);
        s.recordLifetime = 0;
        return Sequence(t.scene, t.render, s);
    }
};

}  // namespace

// A frame is rendered as if it were the first: its passes are numbered afresh (they seed its records), and,
// with records of one instant each (-at 0), the records of other instants never serve it. So the frame at 20 s
// after the one at 10 s is the frame at 20 s of a fresh sequence, pixel for pixel; and denser smoke darkens it.
TEST(Sequence, EachFrameIsRenderedAsInAFreshSequence) {
    SmokeInTime smoke;
    Sequence sequence = smoke.fresh();
    std::vector<float> at10 = smoke.frame(sequence, 10), at20 = smoke.frame(sequence, 20);
    Sequence fresh10 = smoke.fresh(), fresh20 = smoke.fresh();
    EXPECT_EQ(at10, smoke.frame(fresh10, 10));
    EXPECT_EQ(at20, smoke.frame(fresh20, 20));
    double sum10 = 0, sum20 = 0;
    for (size_t i = 0; i < at10.size(); ++i) sum10 += at10[i], sum20 += at20[i];
    EXPECT_LT(sum20, 0.95 * sum10);
}

namespace {

// The downward sensors (all of whose light is indirect) at each instant of a walk through time: their means,
// their values, and how many records' light was traced.
struct Walk {
    std::vector<double> means;
    uint64_t traced = 0;  // records whose light was traced
    std::vector<std::vector<double>> values;
};
Walk walk(const TestScene& t, const RenderSettings& s, const std::vector<double>& instants) {
    Sequence sequence(t.scene, t.render, s);
    Walk w;
    for (double time : instants) {
        Sensors sensors(sequence, 169, time);
        w.means.push_back(sensors.mean());
        w.values.push_back(sensors.values);
    }
    w.traced = sequence.tracedRecords();
    return w;
}

std::vector<double> instantsFrom(double first, double last, double step) {
    std::vector<double> out;
    for (double t = first; t <= last + 1e-9; t += step) out.push_back(t);
    return out;
}

}  // namespace

// Smoke thickening linearly from 10 to 20 s, the sensors (all of whose light is indirect) at every second: with
// records serving windows of time (-at 32) the light is within -aa/4 of path tracing's (-ad 1024, its mean over
// 169 sensors within 0.3 %) plus the cache's own error at one instant (1 %), while fewer records are traced
// than with records of one instant each (-at 0), which remakes them at every instant: 0.59 of them (the light
// halves in 10 s, and windows of a few seconds serve a few instants each, at two records a window). (The
// light falls convexly in time: linear interpolation between a window's records lies above it.)
TEST(Sequence, RecordsServeWindowsOfTimeWithinTheAccuracy) {
    RayPathDir dir;
    TestScene t{smokeInTime(dir)};
    const std::vector<double> instants = instantsFrom(10, 19, 1);
    RenderSettings paths = settings(0);
    paths.ambientDivisions = 1024;
    RenderSettings windows = settings(0.1), single = settings(0.1);
    single.recordLifetime = 0;
    Walk reference = walk(t, paths, instants), through = walk(t, windows, instants), each = walk(t, single, instants);
    for (size_t i = 0; i < instants.size(); ++i)
        EXPECT_NEAR(through.means[i], reference.means[i], (0.25 * 0.1 + 0.01) * reference.means[i]) << instants[i];
    EXPECT_LT(double(through.traced), 0.7 * double(each.traced));
    EXPECT_LT(reference.means.back(), 0.7 * reference.means.front());  // the smoke does dim the light
}

// Records serving windows of time are made in an order the items fix: the same values on one thread or two.
TEST(Sequence, RecordsThroughTimeAreTheSameOnOneOrTwoThreads) {
    RayPathDir dir;
    TestScene t{smokeInTime(dir)};
    auto values = [&](int threads) {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
        return walk(t, settings(0.1), instantsFrom(10, 13, 1)).values;
    };
    EXPECT_EQ(values(1), values(2));
}

// Where nothing changes in time, the records of the first instant serve every later one: the same numbers at
// every instant, bit for bit, and no sensor runs again after the first instant.
TEST(Sequence, StaticScenesGiveTheSameNumbersAtEveryInstant) {
    TestScene t(kRoom);
    Walk w = walk(t, settings(0.1), {0, 1, 2, 50});
    for (size_t i = 1; i < w.values.size(); ++i) EXPECT_EQ(w.values[i], w.values[0]) << i;
    Sequence sequence(t.scene, t.render, settings(0.1));
    Sensors first(sequence, 169, 0), later(sequence, 169, 7);
    EXPECT_EQ(later.runsInAll(), 169);
}

// A step in the smoke (thin until 15 s, thick from 15.1 s; the light falls by 58 %): records made before it
// serve windows that end before it, or straddle it by little enough that their halves' changes differ by at
// most -aa: a second before it and after it the light is the thin and the thick smoke's, as with records of
// one instant each (within 2 %: the caches' own errors); at its start, within -aa plus 3 % (the records' own
// noise, which the halves' changes carry, twice 1.5 %).
TEST(Sequence, AStepInTheSmokeIsNotSmearedAcrossIt) {
    RayPathDir dir;
    using namespace medium::testing;
    writeGrid(dir.path() / "thin.vdb", boxGrid({0, 0, 0}, {19, 19, 19}, 1.0f, 0.1));
    writeGrid(dir.path() / "thick.vdb", boxGrid({0, 0, 0}, {19, 19, 19}, 4.0f, 0.1));
    std::string scene = smokeInTime(dir);
    scene = scene.substr(0, scene.find("void smoke")) +
            "void smoke s 8 10 thin.vdb 15 thin.vdb 15.1 thick.vdb 25 thick.vdb 0 3 .5 .5 .5\n";
    TestScene t{scene};
    const std::vector<double> instants = instantsFrom(10, 20, 1);
    RenderSettings single = settings(0.1);
    single.recordLifetime = 0;
    Walk through = walk(t, settings(0.1), instants), each = walk(t, single, instants);
    for (size_t i = 0; i < instants.size(); ++i)
        EXPECT_NEAR(through.means[i], each.means[i], (instants[i] == 15 ? 0.13 : 0.02) * each.means[i]) << instants[i];
    EXPECT_LT(each.means.back(), 0.5 * each.means.front());
}
