// Records made where lookups missed them, in an order fixed by the work, not by the threads. A loop over work
// items (lib/render's Sequence) runs them in passes against a store that does not change while a pass runs;
// each item notes in its CacheVisit the records it missed; between passes, makeRecords makes the ones the
// store accepts.
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <iterator>
#include <vector>

#include <tbb/parallel_for.h>

#include "cache/record_request.h"
#include "sampling/random.h"

namespace brume {

// What one work item, or one record's own rays, learns from the cache: the records its lookups missed.
struct CacheVisit {
    bool waits = false;   // a work item waits for the records it misses (and runs again); records' rays do not
    bool missed = false;  // it missed one it waits for
    uint64_t key = 0;     // seeds the requests: key and count
    uint64_t count = 0;
    std::vector<RecordRequest> requests;

    // Notes a lookup that found no record: a request for one there, seeded by the visit's key and count.
    // True when the item waits for the record: what it computes now is moot, it runs again.
    bool miss(const Receiver& at, const SurfaceId& leaving, float weight) {
        requests.push_back({at, leaving, weight, mixBits(key + ++count)});
        missed = missed || waits;
        return waits;
    }
};

// Makes the records `store` accepts of these requests (see RecordStore::accept; `missesToPay` tells what a
// record is worth), kRecordsPerRound at a time on all threads: make(request, visit) computes those of one
// request (a window's, RecordWindows), noting in `visit` (seeded by the request) what their own rays missed;
// those requests, of deeper bounces and of either kind of record, go to serveDeeper before the next round, so
// that later records use the records they bring.
// A round leaves out the requests whose points the records of the rounds before it hold: accept() takes one
// request per region, and where the zones made are far larger than the regions (in open smoke, zones of
// 0.3 m beside regions sized by the centimetre zones near walls), a pass whose lookups missed everywhere in
// a volume would fill it with records of one another's zones (in the smoky corridor's 160 x 120 picture,
// lookups were held by 79 records on average and up to 1300, which cost 62 % of the run).
template <class Store, class Make, class ServeDeeper>
void makeRecords(Store& store, const std::vector<RecordRequest>& requests,
                 const std::function<int(const RecordRequest&)>& missesToPay, const Make& make,
                 const ServeDeeper& serveDeeper) {
    constexpr size_t kRecordsPerRound = 64;  // made together; the next ones may use them
    const std::vector<RecordRequest> accepted = store.accept(requests, missesToPay);
    for (size_t next = 0; next < accepted.size();) {
        std::vector<RecordRequest> round;
        for (; next < accepted.size() && round.size() < kRecordsPerRound; ++next)
            if (!store.holds(accepted[next].at)) round.push_back(accepted[next]);
        const size_t n = round.size();
        std::vector<std::vector<typename Store::Record>> made(n);
        std::vector<CacheVisit> visits(n);
        tbb::parallel_for(size_t(0), n, [&](size_t i) {
            visits[i].key = round[i].key;
            made[i] = make(round[i], visits[i]);
        });
        std::vector<typename Store::Record> records;
        for (auto& some : made) std::move(some.begin(), some.end(), std::back_inserter(records));
        store.insert(std::move(records));
        std::vector<RecordRequest> deeper;
        for (const CacheVisit& v : visits) deeper.insert(deeper.end(), v.requests.begin(), v.requests.end());
        if (!deeper.empty()) serveDeeper(deeper);
    }
}

}  // namespace brume
