// The irradiance cache as paths use it: lookups that find records, or note a request for one (and make the
// work item wait for it, or let the path sample the light itself); and records made of a hemisphere of rays,
// here in a uniform surrounding of radiance L (a tracer that answers every ray with L).
#include "integrator/cache_client.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrator/testing.h"
#include "medium/testing.h"
#include "ray_path_dir.h"

using namespace brume;
using namespace brume::integrator_testing;
using std::numbers::pi;

namespace {

const std::string kFloor = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
constexpr float kL = 2;

RenderSettings cached(int ad = 64) {
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = 1, s.ambientAccuracy = 0.1, s.ambientDivisions = ad;
    return s;
}

// A cache of the settings' accuracy (its other bounds matter little here).
struct Cache {
    SurfaceCache store{SurfaceZones(RecordShape{}), dvec3(0)};
};

// A floor point, looked up by a path of weight .3 through a lobe of coefficient 1 at diffuse bounce 0, instant
// 3.5 (the scene is static: one set of records serves every instant).
struct Lookup {
    Parts& parts;
    Receiver at{dvec3(0.3, -0.4, 0), dvec3(0, 0, 1), 0, 3.5};
    SurfaceId floor = parts.hit(dvec3(0.3, -0.4, 1), dvec3(0, 0, -1)).surface;

    bool irradiance(CacheVisit* visit, Spectrum& value) {
        PathContext ctx = parts.context(1, visit);
        return parts.cache.irradiance(at, floor, 0.3, Spectrum(1.f), ctx, value);
    }
    RecordRequest request() const { return {at, floor, 1, 9}; }
};

// The rays of a record asked by a lookup at diffuse bounce `level` by a ray of weight `weight`.
int divisions(const Parts& parts, int level, float weight) {
    RecordRequest q;
    q.at.level = level, q.weight = weight;
    return parts.cache.recordDivisions(q);
}

CacheVisit waiting() {
    CacheVisit v;
    v.waits = true;
    return v;
}

// A record made in a uniform surrounding of radiance L (the tracer's), at the lookup's point.
SurfaceRecord uniformRecord(Parts& parts, const Lookup& lookup, CacheVisit& visit) {
    parts.tracer.value = Spectrum(kL);
    std::vector<SurfaceRecord> records = parts.cache.makeRecords(lookup.request(), nullptr, parts.scratch, visit);
    EXPECT_EQ(records.size(), 1u);  // the scene is static: one record serves every instant
    return records.at(0);
}

}  // namespace

// Without a cache (-aa 0), or outside a loop over work items (no visit), lookups find nothing and note nothing:
// paths sample the light themselves.
TEST(CacheClient, WithoutACacheOrAVisitNothingIsLookedUp) {
    Parts none(kFloor, cached());
    CacheVisit visit = waiting();
    Spectrum value;
    EXPECT_FALSE(Lookup{none}.irradiance(&visit, value));
    EXPECT_TRUE(visit.requests.empty());
    Cache cache;
    Parts parts(kFloor, cached(), &cache.store);
    EXPECT_FALSE(Lookup{parts}.irradiance(nullptr, value));
}

// A miss notes one request (the receiver, the surface its rays will leave, the looking ray's weight). A work
// item that waits gets 0 (moot: it runs again once the record is made); a record's own rays, which do not
// wait, sample the light themselves.
TEST(CacheClient, AMissNotesARequestAndAWaitingItemGetsZero) {
    Cache cache;
    Parts parts(kFloor, cached(), &cache.store);
    Lookup lookup{parts};
    CacheVisit visit = waiting();
    Spectrum value(7.f);
    EXPECT_TRUE(lookup.irradiance(&visit, value));
    EXPECT_TRUE(value.isBlack());
    EXPECT_TRUE(visit.missed);
    ASSERT_EQ(visit.requests.size(), 1u);
    const RecordRequest& q = visit.requests[0];
    EXPECT_EQ(q.at.point, lookup.at.point);
    EXPECT_EQ(q.at.normal, lookup.at.normal);
    EXPECT_EQ(q.at.level, 0);
    EXPECT_EQ(q.at.time, 3.5);
    EXPECT_EQ(q.leaving, lookup.floor);
    EXPECT_EQ(q.weight, 0.3f);
    CacheVisit recordsRays;
    EXPECT_FALSE(lookup.irradiance(&recordsRays, value));
    EXPECT_FALSE(recordsRays.missed);
    EXPECT_EQ(recordsRays.requests.size(), 1u);
}

// In a uniform surrounding of radiance L a record holds E = πL (its cosine-weighted strata sum it exactly:
// 1e-5) and no translational gradient (neighbouring strata agree: 1e-5 E); it is of the request's bounce and
// serves every instant (the scene is static), made of about -ad rays (64 ± 8: whole rows and columns), each a
// sampled path one bounce deeper leaving the floor upward. Inserted, it serves lookups there.
TEST(CacheClient, ARecordInAUniformSurroundingHoldsPiL) {
    Cache cache;
    Parts parts(kFloor, cached(64), &cache.store);
    Lookup lookup{parts};
    CacheVisit visit;
    SurfaceRecord record = uniformRecord(parts, lookup, visit);
    const double E = pi * kL;
    EXPECT_NEAR(record.field(SurfaceRecord::kIrradiance)[0], E, 1e-5 * E);
    for (auto gradient : {SurfaceRecord::kAlongK1, SurfaceRecord::kAlongK2})
        EXPECT_NEAR(record.field(gradient)[0], 0, 1e-5 * E) << gradient;
    EXPECT_EQ(record.level, 0);
    EXPECT_EQ(record.when.weightAt(-1e9), 1.0);
    EXPECT_EQ(record.when.weightAt(3.5), 1.0);
    EXPECT_EQ(record.point, lookup.at.point);
    EXPECT_NEAR(double(parts.tracer.rays.size()), 64, 8);
    for (const AskedRay& r : parts.tracer.rays) {
        EXPECT_GT(r.ray.dir.z, 0);
        EXPECT_EQ(r.ray.leaving, lookup.floor);
        EXPECT_EQ(r.state.kind, PathState::Kind::Sampled);
        EXPECT_EQ(r.state.ambientLevel, 1);
    }
    EXPECT_TRUE(visit.requests.empty());  // the tracer looked nothing up
    cache.store.insert({record});
    Spectrum value;
    CacheVisit next = waiting();
    ASSERT_TRUE(lookup.irradiance(&next, value));
    EXPECT_NEAR(value[0], E, 1e-5 * E);
    EXPECT_TRUE(next.requests.empty());
}

// A first-bounce surface record's passes follow its standard error against all the light its surface gets.
// Where every other ray brings 0 or 2L at random, the first pass's relative error is about 1/√64 = 12 %, eight
// times and more the 1.5 % -aa .1 asks for: eight passes (the most), 512 rays. Under a lamp whose light
// straight on the floor is some 20 times the rest (a 1 m square of radiance 200, 1 m up: E ≈ 140), the same
// noise is 0.6 % of the whole: one pass. A lamp under the floor, behind it, lights nothing there: eight.
TEST(CacheClient, ASurfaceRecordsPassesFollowItsStandardErrorAgainstAllItsLight) {
    auto rays = [](const std::string& lamp) {
        Cache cache;
        Parts parts(kFloor + "void light bright 0 0 3 200 200 200\n" + lamp, cached(64), &cache.store);
        parts.tracer.byRay = [](const Ray& ray) {
            double hash = std::sin(glm::dot(ray.dir, dvec3(12.9898, 78.233, 37.719)) * 43758.5453);
            return Spectrum(hash - std::floor(hash) < 0.5 ? 0.f : 2 * kL);
        };
        Lookup lookup{parts};
        CacheVisit visit;
        parts.cache.makeRecords(lookup.request(), nullptr, parts.scratch, visit);
        return double(parts.tracer.rays.size());
    };
    const std::string above = "bright polygon over 0 0 12  -.2 -.9 1  -.2 .1 1  .8 .1 1  .8 -.9 1\n";
    const std::string under = "bright polygon beneath 0 0 12  -.2 -.9 -1  .8 -.9 -1  .8 .1 -1  -.2 .1 -1\n";
    EXPECT_NEAR(rays(""), 512, 64);
    EXPECT_NEAR(rays(above), 64, 8);
    EXPECT_NEAR(rays(under), 512, 64);
}

// A first-bounce volume record's sphere: a first pass of a quarter of -ad, then more passes where its rays'
// standard error, against all the light, asks for them. In a uniform surrounding the strata agree (no error):
// one pass, 256 / 4 rays (± 8: whole rows and columns), its mean L (1e-5). Where every other ray brings 0 or
// 2L at random, the first pass's relative error is about 1/√64 = 12 %, four times and more the 3 % -aa .1
// asks for: four passes in all, -ad rays. Deeper records make one pass of all their rays.
TEST(CacheClient, AVolumeRecordsPassesFollowItsStandardError) {
    VolumeCache volumes{VolumeZones(RecordShape{}), dvec3(0)};
    Parts parts(kFloor, cached(256), nullptr, &volumes);
    RecordRequest q{Receiver{dvec3(0, 0, 1), std::nullopt, 0, 0.0}, SurfaceId{}, 1, 9};
    auto rays = [&](int level) {
        parts.tracer.rays.clear();
        q.at.level = level;
        CacheVisit visit;
        VolumeRecord record = parts.cache.makeVolumeRecords(q, nullptr, parts.scratch, visit).at(0);
        return std::pair{double(parts.tracer.rays.size()), double(record.meanRadiance()[0])};
    };
    parts.tracer.value = Spectrum(kL);
    auto [uniform, mean] = rays(0);
    EXPECT_NEAR(uniform, 64, 8);
    EXPECT_NEAR(mean, kL, 1e-5 * kL);
    parts.tracer.byRay = [](const Ray& ray) {
        double hash = std::sin(glm::dot(ray.dir, dvec3(12.9898, 78.233, 37.719)) * 43758.5453);
        return Spectrum(hash - std::floor(hash) < 0.5 ? 0.f : 2 * kL);
    };
    EXPECT_NEAR(rays(0).first, 256, 32);
    EXPECT_NEAR(rays(1).first, 256, 32);
}

// Radiance's -ad at the first bounce; deeper, scaled by the looking ray's weight, but never below 16 rays
// (nor above -ad).
TEST(CacheClient, RecordDivisionsScaleWithTheWeightBelowTheFirstBounce) {
    Parts parts(kFloor, cached(400));
    EXPECT_EQ(divisions(parts, 0, 0.1f), 400);
    EXPECT_EQ(divisions(parts, 1, 0.5f), 200);
    EXPECT_EQ(divisions(parts, 2, 1.f), 400);
    EXPECT_EQ(divisions(parts, 1, 0.01f), 16);
    Parts few(kFloor, cached(8));
    EXPECT_EQ(divisions(few, 1, 0.01f), 8);
}

// A volume record's zone reaches no further into denser smoke than a record made there would: ε over the
// largest extinction of its point and edge. Smoke of density 1 for x < 4.95 m and 20 beyond (voxels of 0.1 m,
// trilinear between 4.9 and 5), K 1 /m, -aa .1: a record at x 4.85 would reach 0.1 m (ε / σ_t at its point),
// to x 4.95 where σ_t is 10.5: held at 0.1 / 10.5. Deep in the thin side it keeps its 0.1 m; and near a lamp
// the zone's edge stays within √ε of the edge's own distance.
TEST(CacheClient, AVolumeRecordsZoneStopsWhereItsEdgeNeedsIt) {
    RayPathDir dir;
    auto grid = brume::medium::testing::boxGrid({0, 0, 0}, {99, 99, 99}, 1.0f, 0.1);
    grid->tree().fill(openvdb::CoordBBox(openvdb::Coord(50, 0, 0), openvdb::Coord(99, 99, 99)), 20.0f, true);
    brume::medium::testing::writeGrid(dir.path() / "step.vdb", grid);
    VolumeCache volumes{VolumeZones(RecordShape{}), dvec3(0)};
    auto radius = [&](const std::string& scene, const dvec3& p) {
        Parts parts(scene + "void smoke s 1 step.vdb 0 3 1 1 1\n", cached(64), nullptr, &volumes);
        parts.tracer.value = Spectrum(kL);
        RecordRequest q{Receiver{p, std::nullopt, 1, 0.0}, SurfaceId{}, 1, 9};
        CacheVisit visit;
        return double(parts.cache.makeVolumeRecords(q, nullptr, parts.scratch, visit).at(0).radius);
    };
    EXPECT_NEAR(radius("", dvec3(2, 5, 5)), 0.1, 1e-6);
    EXPECT_NEAR(radius("", dvec3(4.85, 5, 5)), 0.1 / 10.5, 1e-4);
    const std::string lamp = "void light bright 0 0 3 100 100 100\nbright sphere bulb 0 0 4 2 5 5.4 0.01\n";
    const double distance = 0.4 - 0.01, share = std::sqrt(0.1) / (1 + std::sqrt(0.1));
    EXPECT_NEAR(radius(lamp, dvec3(2, 5, 5)), std::min(0.1, share * distance), 1e-6);
}

