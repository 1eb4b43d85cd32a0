// Records made where lookups missed them, in an order fixed by the work, not by the threads. A loop over work
// items (lib/render's Sequence) runs them in passes against a store that does not change while a pass runs;
// each item notes in its CacheVisit the records it missed; between passes, makeRecords makes the ones the
// store accepts.
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <tbb/parallel_for.h>

#include "cache/record_request.h"
#include "cache/record_windows.h"
#include "sampling/random.h"

namespace brume {

// What one work item, or one record's own rays, learns from the cache: the records its lookups missed.
struct CacheVisit {
    bool waits = false;   // a work item waits for the records it misses (and runs again); records' rays do not
    bool missed = false;  // it missed one it waits for
    uint64_t key = 0;     // seeds the requests: key and count
    uint64_t count = 0;
    std::vector<RecordRequest> requests;
    uint64_t traced = 0;  // records whose light its rays traced (a request's: one, or a window's several)

    // Notes a lookup that found no record: a request for one there, seeded by the visit's key and count.
    // True when the item waits for the record: what it computes now is moot, it runs again.
    bool miss(const Receiver& at, const SurfaceId& leaving, float weight) {
        requests.push_back({at, leaving, weight, mixBits(key + ++count)});
        missed = missed || waits;
        return waits;
    }
};

// Makes the records `store` accepts of these requests (see RecordStore::accept; `missesToPay` tells what a
// record is worth), kRecordsPerRound at a time on all threads: make(request, open, visit) computes those of
// one request — of its instant, or, where `open` (the open record a window may start from, RecordWindows,
// else null), the window's —, noting in `visit` (seeded by the request) what their own rays missed; those
// requests, of deeper bounces and of either kind of record, go to serveDeeper before the next round, so that
// later records use the records they bring. Records of one instant are left open where `windows` open them;
// an open record starts one window (requests of a round that would start a second from it are left out: if
// the first does not serve them, they miss again).
// Returns how many records' light was traced (CacheVisit::traced), not counting serveDeeper's.
// A round leaves out the requests whose points the records of the rounds before it hold: accept() takes one
// request per region, and where the zones made are far larger than the regions (in open smoke, zones of
// 0.3 m beside regions sized by the centimetre zones near walls), a pass whose lookups missed everywhere in
// a volume would fill it with records of one another's zones (in the smoky corridor's 160 x 120 picture,
// lookups were held by 79 records on average and up to 1300, which cost 62 % of the run).
template <class Store, class Make, class ServeDeeper>
uint64_t makeRecords(Store& store, const std::vector<RecordRequest>& requests,
                 const std::function<int(const RecordRequest&)>& missesToPay, const RecordWindows& windows,
                 const Make& make, const ServeDeeper& serveDeeper) {
    using Record = typename Store::Record;
    constexpr size_t kRecordsPerRound = 64;  // made together; the next ones may use them
    const std::vector<RecordRequest> accepted = store.accept(requests, missesToPay);
    uint64_t traced = 0;
    for (size_t next = 0; next < accepted.size();) {
        std::vector<RecordRequest> round;
        std::vector<std::optional<size_t>> from;  // the open record each starts a window from
        for (; next < accepted.size() && round.size() < kRecordsPerRound; ++next) {
            const RecordRequest& q = accepted[next];
            if (store.holds(q.at)) continue;
            std::optional<size_t> open = windows.opens() ? store.openFor(q.at, windows) : std::nullopt;
            if (open && std::find(from.begin(), from.end(), open) != from.end()) continue;
            round.push_back(q);
            from.push_back(open);
        }
        const size_t n = round.size();
        std::vector<std::optional<OpenRecord<Record>>> opens(n);
        for (size_t i = 0; i < n; ++i)
            if (from[i]) opens[i] = store.open(*from[i]);
        std::vector<std::vector<Record>> made(n);
        std::vector<CacheVisit> visits(n);
        tbb::parallel_for(size_t(0), n, [&](size_t i) {
            visits[i].key = round[i].key;
            made[i] = make(round[i], opens[i] ? &*opens[i] : nullptr, visits[i]);
        });
        std::vector<Record> records;
        std::vector<std::optional<RecordRequest>> opened;
        for (size_t i = 0; i < n; ++i) {
            traced += visits[i].traced;
            if (from[i]) store.close(*from[i]);
            for (Record& r : made[i]) {
                std::optional<RecordRequest> request;
                if (windows.opens() && r.when.from == r.when.to) {
                    request = opens[i] ? opens[i]->request : round[i];
                    request->at.time = r.when.at;
                }
                opened.push_back(request);
                records.push_back(std::move(r));
            }
        }
        store.insert(std::move(records), std::move(opened));
        std::vector<RecordRequest> deeper;
        for (const CacheVisit& v : visits) deeper.insert(deeper.end(), v.requests.begin(), v.requests.end());
        if (!deeper.empty()) serveDeeper(deeper);
    }
    return traced;
}

}  // namespace brume
