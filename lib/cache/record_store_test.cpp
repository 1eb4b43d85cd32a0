// Lookups, acceptance of requests and the splotch control of the surface irradiance cache, and its windows
// of time, on hand-made records.
#include "cache/surface_cache.h"

#include <gtest/gtest.h>

using namespace brume;

namespace {

RecordShape shape() {
    RecordShape s;
    s.accuracy = 0.1;
    s.minRadius = 0.01;
    s.maxRadius = 1;
    return s;
}

SurfaceCache cacheOf() { return SurfaceCache(SurfaceZones(shape()), dvec3(0)); }

Receiver at(const dvec3& p, const dvec3& n = dvec3(0, 0, 1), int level = 0, double time = 0) { return {p, n, level, time}; }

SurfaceRecord record(const dvec3& p, float e, float r0, float r1, int level = 0, float gradK1 = 0) {
    SurfaceRecord r;
    r.point = p;
    r.normal = dvec3(0, 0, 1);
    r.axis = dvec3(1, 0, 0);
    r.radius[0] = r0, r.radius[1] = r1;
    r.level = level;
    r.setField(SurfaceRecord::kIrradiance, Spectrum(e));
    for (auto f : {SurfaceRecord::kAlongK1, SurfaceRecord::kAlongK2, SurfaceRecord::kTiltK1,
                   SurfaceRecord::kTiltK2})
        r.setField(f, Spectrum(0.f));
    r.setField(SurfaceRecord::kAlongK1, Spectrum(gradK1));
    return r;
}

}  // namespace

TEST(SurfaceCache, LooksUpInsideTheEllipseOnly) {
    SurfaceCache cache = cacheOf();
    std::vector<SurfaceRecord> records{record(dvec3(0), 2, 0.1f, 0.4f)};
    cache.insert(records);
    Spectrum e;
    ASSERT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0), e));
    EXPECT_FLOAT_EQ(e[0], 2);
    EXPECT_TRUE(cache.lookup(at(dvec3(0, 0.3, 0), dvec3(0, 0, 1), 0), e));    // along the long axis
    EXPECT_FALSE(cache.lookup(at(dvec3(0.15, 0, 0), dvec3(0, 0, 1), 0), e));  // beyond the short one
    EXPECT_FALSE(cache.lookup(at(dvec3(0, 0, -0.05), dvec3(0, 0, 1), 0), e));  // behind its plane
    EXPECT_FALSE(cache.lookup(at(dvec3(0), glm::normalize(dvec3(1, 0, 1)), 0), e));  // 45°: beyond 10° + ε
    EXPECT_TRUE(cache.lookup(at(dvec3(0), glm::normalize(dvec3(0.1, 0, 1)), 0), e));
    EXPECT_LT(e[0], 2);  // the second-order tilt term: E(1 − α²/2)
}

TEST(SurfaceCache, DeeperRecordsServeOnlyDeeperLookups) {
    SurfaceCache cache = cacheOf();
    cache.insert({record(dvec3(0), 1, 0.2f, 0.2f, 2)});
    Spectrum e;
    EXPECT_FALSE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 1), e));
    EXPECT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 2), e));
    EXPECT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 3), e));
}

// Extrapolation by the gradient, and Ribardière's weight: (|RP'|/|RP| − 1) at equal normals.
TEST(SurfaceCache, InterpolatesExtrapolationsByTheZoneWeight) {
    SurfaceCache cache = cacheOf();
    cache.insert({record(dvec3(0), 1, 1, 1, 0, 2.f), record(dvec3(1, 0, 0), 4, 1, 1)});
    Spectrum e;
    ASSERT_TRUE(cache.lookup(at(dvec3(0.25, 0, 0), dvec3(0, 0, 1), 0), e));
    double first = 1 + 2 * 0.25, w1 = 1 / 0.25 - 1, w2 = 1 / 0.75 - 1;
    EXPECT_NEAR(e[0], (w1 * first + w2 * 4) / (w1 + w2), 1e-5);
    // The gradient's change is clamped to the value itself: never negative, at most double.
    SurfaceCache steep = cacheOf();
    steep.insert({record(dvec3(0), 1, 1, 1, 0, -10.f)});
    ASSERT_TRUE(steep.lookup(at(dvec3(0.5, 0, 0), dvec3(0, 0, 1), 0), e));
    EXPECT_EQ(e[0], 0);
}

// Requests wait until enough misses in their region pay for a record; one record per region at a time.
TEST(SurfaceCache, AcceptsOneRequestPerRegionOnceMissesPayForIt) {
    SurfaceCache cache = cacheOf();
    std::vector<RecordRequest> requests;
    for (int i = 0; i < 5; ++i) requests.push_back({at(dvec3(0.01 * i, 0, 0), dvec3(0, 0, 1), 1), {}, 1, uint64_t(i)});
    auto three = [](const RecordRequest&) { return 3; };
    std::vector<RecordRequest> accepted = cache.accept(requests, three);
    ASSERT_EQ(accepted.size(), 1u);
    EXPECT_EQ(accepted[0].key, 0u);  // the region's first
    // Then the region counts afresh.
    EXPECT_TRUE(cache.accept({requests[0], requests[1]}, three).empty());
    EXPECT_EQ(cache.accept({requests[2]}, three).size(), 1u);
    // Where a record now covers the point, nothing is accepted.
    cache.insert({record(dvec3(0), 1, 0.5f, 0.5f, 1)});
    EXPECT_TRUE(cache.accept(requests, [](const RecordRequest&) { return 1; }).empty());
}

// Requests at sensors however far out (1e300, -1e300) are counted in regions of their own side: two far
// apart never pay for each other's record; two at one far point do.
TEST(SurfaceCache, FarRequestsKeepToTheirOwnRegions) {
    SurfaceCache cache = cacheOf();
    auto two = [](const RecordRequest&) { return 2; };
    RecordRequest east{at(dvec3(1e300, 0, 0), dvec3(0, 0, 1), 1), {}, 1, 1}, west{at(dvec3(-1e300, 0, 0), dvec3(0, 0, 1), 1), {}, 1, 2};
    EXPECT_TRUE(cache.accept({east, west}, two).empty());
    std::vector<RecordRequest> accepted = cache.accept({east}, two);
    ASSERT_EQ(accepted.size(), 1u);
    EXPECT_EQ(accepted[0].key, 1u);
}

// Two records of one bounce that disagree beyond twice the accuracy at each other's points shrink apart.
TEST(SurfaceCache, DisagreeingRecordsShrinkSoNeitherSpeaksForTheOther) {
    SurfaceCache cache = cacheOf();
    cache.insert({record(dvec3(0), 1, 0.5f, 0.5f)});
    cache.insert({record(dvec3(0.3, 0, 0), 2, 0.5f, 0.5f)});
    EXPECT_LT(cache.records()[0].radius[0], 0.31f);
    EXPECT_LT(cache.records()[1].radius[0], 0.31f);
    // Agreeing ones keep their zones.
    SurfaceCache calm = cacheOf();
    calm.insert({record(dvec3(0), 1, 0.5f, 0.5f)});
    calm.insert({record(dvec3(0.3, 0, 0), 1.05f, 0.5f, 0.5f)});
    EXPECT_EQ(calm.records()[0].radius[0], 0.5f);
    EXPECT_EQ(calm.records()[1].radius[0], 0.5f);
}

// Many records through the BVH: a lookup finds exactly the records whose zones hold the point.
TEST(SurfaceCache, IndexFindsTheSameRecordsAsAScan) {
    SurfaceCache cache = cacheOf();
    std::vector<SurfaceRecord> records;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) records.push_back(record(dvec3(0.1 * i, 0.1 * j, 0), float(1 + i), 0.07f, 0.07f));
    cache.insert(records);
    Spectrum e;
    for (int i = 0; i < 40; ++i) {
        ASSERT_TRUE(cache.lookup(at(dvec3(0.1 * i, 0.05, 0), dvec3(0, 0, 1), 0), e));
        EXPECT_FLOAT_EQ(e[0], float(1 + i));
    }
    EXPECT_FALSE(cache.lookup(at(dvec3(-0.5, 0, 0), dvec3(0, 0, 1), 0), e));
}

// Records of one instant serve that instant alone: lookups at another find nothing, records of other
// instants neither blend with them nor shrink them, misses are counted per instant, and a run that moves on
// forgets the records whose instants are behind it.
TEST(SurfaceCache, RecordsOfOneInstantServeItAlone) {
    SurfaceCache cache = cacheOf();
    SurfaceRecord early = record(dvec3(0), 1, 0.5f, 0.5f), late = record(dvec3(0), 3, 0.5f, 0.5f);
    early.when = RecordTime::instant(60), late.when = RecordTime::instant(120);
    cache.insert({early, late});
    Spectrum e;
    ASSERT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 60), e));
    EXPECT_FLOAT_EQ(e[0], 1);
    ASSERT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 120), e));
    EXPECT_FLOAT_EQ(e[0], 3);
    EXPECT_FALSE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 90), e));
    EXPECT_EQ(cache.records()[0].radius[0], 0.5f);
    RecordRequest a{at(dvec3(2, 0, 0), dvec3(0, 0, 1), 0, 60), {}, 1, 1}, b{at(dvec3(2, 0, 0), dvec3(0, 0, 1), 0, 90), {}, 1, 2};
    EXPECT_TRUE(cache.accept({a, b}, [](const RecordRequest&) { return 2; }).empty());
    cache.takeUnsaved();
    cache.forgetBefore(120, 120);
    EXPECT_FALSE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 60), e));
    EXPECT_TRUE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 120), e));
    EXPECT_EQ(cache.size(), 1u);
    // The misses counted at 60 and 90 were forgotten with them: one more at 60 pays for nothing.
    EXPECT_TRUE(cache.accept({a}, [](const RecordRequest&) { return 2; }).empty());
}

// A window's three records (instants 0, 2, 4 of [0, 4)) interpolate linearly in time between the two nearest
// (exact, to float rounding); the window's end belongs to the next one. Records of every instant serve every
// instant and are never forgotten.
TEST(SurfaceCache, AWindowsRecordsInterpolateInTime) {
    SurfaceCache cache = cacheOf();
    std::vector<SurfaceRecord> three;
    for (auto [t, e] : {std::pair{0.0, 1.f}, {2.0, 2.f}, {4.0, 5.f}}) {
        three.push_back(record(dvec3(0), e, 0.5f, 0.5f));
        three.back().when = RecordTime{t, 0, 4, 2};
    }
    cache.insert(three);
    Spectrum e;
    for (auto [t, expected] : {std::pair{0.0, 1.f}, {1.0, 1.5f}, {2.0, 2.f}, {3.0, 3.5f}, {3.75, 4.625f}}) {
        ASSERT_TRUE(cache.lookup(at(dvec3(0.1, 0, 0), dvec3(0, 0, 1), 0, t), e)) << t;
        EXPECT_NEAR(e[0], expected, 1e-6) << t;
    }
    EXPECT_FALSE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 4), e));
    EXPECT_FALSE(cache.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, -0.5), e));
    cache.takeUnsaved();
    cache.forgetBefore(3, 3);
    EXPECT_EQ(cache.size(), 3u);
    cache.forgetBefore(4, 4);
    EXPECT_EQ(cache.size(), 0u);

    SurfaceCache still = cacheOf();
    still.insert({record(dvec3(0), 1, 0.5f, 0.5f)});
    EXPECT_TRUE(still.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, -1e9), e));
    still.takeUnsaved();
    still.forgetBefore(1e9, 1e9);
    EXPECT_TRUE(still.lookup(at(dvec3(0), dvec3(0, 0, 1), 0, 1e9), e));
}

// A run that moves on keeps the records it has not handed out to be saved.
TEST(SurfaceCache, MovingOnStillHandsOutTheRecordsNotYetSaved) {
    SurfaceCache cache = cacheOf();
    SurfaceRecord r = record(dvec3(0), 1, 0.5f, 0.5f);
    r.when = RecordTime::instant(5);
    cache.insert({r});
    cache.forgetBefore(10, 10);
    EXPECT_EQ(cache.size(), 0u);
    ASSERT_EQ(cache.takeUnsaved().size(), 1u);
    EXPECT_TRUE(cache.takeUnsaved().empty());
}

// An open record (of one instant, with the request it was made for) is found by later lookups that its zone
// holds, of its bounce, within -at after it; the latest first. Closed, or older than `openSince` when the run
// moves on, it is not.
TEST(SurfaceCache, OpenRecordsStartWindowsForLaterLookupsTheyHold) {
    SurfaceCache cache = cacheOf();
    RecordWindows windows(true, 100, 32);
    SurfaceRecord early = record(dvec3(0), 1, 0.5f, 0.5f), late = record(dvec3(0.1, 0, 0), 2, 0.5f, 0.5f);
    early.when = RecordTime::instant(5), late.when = RecordTime::instant(8);
    RecordRequest q{at(dvec3(0), dvec3(0, 0, 1), 0, 5), {}, 1, 77};
    cache.insert({early, late}, {q, q});
    EXPECT_EQ(cache.openFor(at(dvec3(0.05, 0, 0), dvec3(0, 0, 1), 0, 20), windows), 1u);
    EXPECT_EQ(cache.open(1).request.key, 77u);
    EXPECT_FALSE(cache.openFor(at(dvec3(0.05, 0, 0), dvec3(0, 0, 1), 1, 20), windows));  // another bounce
    EXPECT_FALSE(cache.openFor(at(dvec3(3, 0, 0), dvec3(0, 0, 1), 0, 20), windows));     // outside the zones
    EXPECT_EQ(cache.openFor(at(dvec3(0.05, 0, 0), dvec3(0, 0, 1), 0, 7), windows), 0u);  // the later is after 7
    EXPECT_FALSE(cache.openFor(at(dvec3(0.05, 0, 0), dvec3(0, 0, 1), 0, 45), windows));  // past -at
    cache.close(1);
    EXPECT_EQ(cache.openFor(at(dvec3(0.05, 0, 0), dvec3(0, 0, 1), 0, 20), windows), 0u);
    cache.takeUnsaved();
    cache.forgetBefore(20, 6);  // the closed one is forgotten, the open one before 6 too
    EXPECT_EQ(cache.size(), 0u);
    cache.insert({early}, {q});
    cache.forgetBefore(20, 4);
    EXPECT_EQ(cache.size(), 1u);
}

// Records made here are handed out once to be saved, those loaded from a file never.
TEST(SurfaceCache, HandsOutTheRecordsMadeSinceTheLastSave) {
    SurfaceCache cache = cacheOf();
    SurfaceRecord loaded = record(dvec3(0), 1, 0.5f, 0.5f), made = record(dvec3(3, 0, 0), 2, 0.5f, 0.5f);
    made.when = RecordTime::instant(5);
    cache.insertSaved({loaded});
    cache.insert({made});
    std::vector<SurfaceRecord> unsaved = cache.takeUnsaved();
    ASSERT_EQ(unsaved.size(), 1u);
    EXPECT_EQ(unsaved[0].point, made.point);
    EXPECT_TRUE(cache.takeUnsaved().empty());
}
