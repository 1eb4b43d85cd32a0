// The records of one kind (surface or volume records), each serving the instants of its window (RecordTime):
// where the scene changes in time, lookups, misses and splotch control take the records of their instant;
// where nothing changes, every record serves every instant.
//
// Lookups run from any number of threads while no record is added; records are added between such passes,
// in the order the caller gives, so what the store holds does not depend on the thread count.
#pragma once
#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "cache/record_layer.h"

namespace brume {

template <class Kind>
class RecordStore {
public:
    using Record = typename Kind::Record;

    // Regions and zone boxes are measured from `origin` (the scene's).
    RecordStore(Kind kind, const dvec3& origin) : kind_(std::move(kind)), records_(kind_, origin) {}
    RecordStore(const RecordStore&) = delete;
    RecordStore& operator=(const RecordStore&) = delete;

    const Kind& kind() const { return kind_; }

    // The value at the receiver from the records of its instant (RecordLayer::lookup); false where none holds it.
    bool lookup(const Receiver& at, Spectrum& value) const { return records_.lookup(at, value); }
    // Whether a record of the receiver's instant holds it.
    bool holds(const Receiver& at) const { return records_.holds(at); }
    // Calls f(record, weight) for each record of the receiver's instant that holds it (RecordLayer::gather);
    // the weights' sum, 0 where none does.
    template <class F>
    double gather(const Receiver& at, F&& f) const {
        return records_.gather(at, f);
    }

    // The requests (taken in their order) that records should be made for now: the first of each region
    // once as many lookups missed there as `missesToPay` says a record is worth (1 for lookups that wait for
    // it), and none where a record made since covers the point at its instant; in the order they came.
    std::vector<RecordRequest> accept(const std::vector<RecordRequest>& requests,
                                      const std::function<int(const RecordRequest&)>& missesToPay) {
        std::vector<typename Layer::RegionKey> ready;
        for (const RecordRequest& q : requests)
            if (auto region = records_.countMiss(q, missesToPay)) ready.push_back(*region);
        std::vector<std::pair<uint64_t, RecordRequest>> accepted;
        for (const auto& key : ready)
            if (auto q = records_.takeRegion(key)) accepted.push_back(*q);
        std::stable_sort(accepted.begin(), accepted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<RecordRequest> out;
        for (auto& [order, q] : accepted) out.push_back(q);
        return out;
    }

    // Adds records made here, in their order, for takeUnsaved; `opened`: the requests open ones were made for
    // (RecordLayer::add).
    void insert(std::vector<Record> records, std::vector<std::optional<RecordRequest>> opened = {}) {
        records_.add(std::move(records), true, std::move(opened));
    }
    // Adds records kept elsewhere (a cache file), in their order.
    void insertSaved(std::vector<Record> records) { records_.add(std::move(records), false); }
    // The records inserted (not insertSaved) since the last call, in their order.
    std::vector<Record> takeUnsaved() {
        std::vector<Record> out;
        records_.takeUnsaved(out);
        return out;
    }
    // Forgets the records whose window is over at instant t but for open ones of instants from `openSince`
    // on (RecordLayer::forgetBefore): a run moving on.
    void forgetBefore(double t, double openSince) { records_.forgetBefore(t, openSince); }
    // The open record a window serving the receiver's instant may start from (RecordLayer::openFor).
    std::optional<size_t> openFor(const Receiver& at, const RecordWindows& windows) const {
        return records_.openFor(at, windows);
    }
    OpenRecord<Record> open(size_t i) const { return records_.open(i); }
    void close(size_t i) { records_.close(i); }

    // Every record, in their order.
    const std::vector<Record>& records() const { return records_.records(); }
    size_t size() const { return records_.records().size(); }
    size_t memoryBytes() const { return records_.memoryBytes(); }
    // "N records (bounce 0: n0, 1: n1, …), M MiB": for progress reports.
    std::string summary() const {
        std::vector<size_t> perLevel;
        for (const Record& r : records_.records()) {
            if (perLevel.size() <= size_t(r.level)) perLevel.resize(r.level + 1);
            ++perLevel[r.level];
        }
        std::string text = std::to_string(size()) + " records (bounce";
        for (size_t l = 0; l < perLevel.size(); ++l)
            text += (l ? ", " : " ") + std::to_string(l) + ": " + std::to_string(perLevel[l]);
        char memory[32];
        std::snprintf(memory, sizeof memory, "), %.1f MiB", memoryBytes() / 1048576.0);
        return text + memory;
    }

private:
    using Layer = RecordLayer<Kind>;

    Kind kind_;
    Layer records_;
};

}  // namespace brume
