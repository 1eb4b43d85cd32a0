// Records made between passes: a round of records leaves out the requests that the records of the rounds
// before it already hold.
#include "cache/record_passes.h"

#include <gtest/gtest.h>

#include <atomic>

#include "cache/surface_cache.h"

using namespace brume;

namespace {

// Requests on a floor 0.6 m apart (each in a region of its own: accept() takes them all), and records made
// there of zones `radius` wide; how many records were made.
size_t recordsMade(float radius) {
    SurfaceCache cache(SurfaceZones(RecordShape{}), dvec3(0));
    std::vector<RecordRequest> requests;
    for (int i = 0; i < 200; ++i)
        requests.push_back({Receiver{dvec3(0.6 * i, 0, 0), dvec3(0, 0, 1), 0, 0}, {}, 1, uint64_t(i)});
    std::atomic<size_t> made = 0;  // make runs on all threads
    auto make = [&](const RecordRequest& q, const OpenRecord<SurfaceRecord>*, CacheVisit&) {
        SurfaceRecord r;
        r.point = q.at.point, r.normal = *q.at.normal, r.axis = dvec3(1, 0, 0);
        r.radius[0] = r.radius[1] = radius;
        for (auto f : {SurfaceRecord::kIrradiance, SurfaceRecord::kAlongK1, SurfaceRecord::kAlongK2,
                       SurfaceRecord::kTiltK1, SurfaceRecord::kTiltK2})
            r.setField(f, Spectrum(f == SurfaceRecord::kIrradiance ? 1.f : 0.f));
        ++made;
        return std::vector<SurfaceRecord>{r};
    };
    makeRecords(cache, requests, [](const RecordRequest&) { return 1; }, RecordWindows(false, 0, 0), make,
                [](const std::vector<RecordRequest>&) {});
    EXPECT_EQ(cache.size(), made.load());
    return made;
}

}  // namespace

// Zones of 0.1 m hold none of the other requests: all 200 are made. Zones of 1 km hold them all: the first
// round's 64 are made together (none held them when it began), the rest left out.
TEST(RecordPasses, ARoundLeavesOutWhatEarlierRoundsHold) {
    EXPECT_EQ(recordsMade(0.1f), 200u);
    EXPECT_EQ(recordsMade(1000.f), 64u);
}
