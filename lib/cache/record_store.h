// The records of one kind (surface or volume records) at the instants in use, each instant's
// in a RecordLayer of its own: where the scene changes in time (InstantKeys) a record holds the light of its own
// instant only, and lookups, misses and splotch control never mix instants; where nothing changes, one layer
// serves every instant.
//
// Lookups run from any number of threads while no record is added; records are added between such passes,
// in the order the caller gives, so what the store holds does not depend on the thread count.
#pragma once
#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cache/record_layer.h"
#include "medium/instant_keys.h"

namespace brume {

template <class Kind>
class RecordStore {
public:
    using Record = typename Kind::Record;

    // Regions and zone boxes are measured from `origin` (the scene's).
    RecordStore(Kind kind, const dvec3& origin, InstantKeys instants)
        : kind_(std::move(kind)), origin_(origin), instants_(instants) {}
    RecordStore(const RecordStore&) = delete;
    RecordStore& operator=(const RecordStore&) = delete;

    const Kind& kind() const { return kind_; }

    // The value at the receiver from the records of its instant (RecordLayer::lookup); false where none holds it.
    bool lookup(const Receiver& at, Spectrum& value) const {
        const Layer* layer = layerAt(at.time);
        return layer && layer->lookup(at, value);
    }
    // Whether a record of the receiver's instant holds it.
    bool holds(const Receiver& at) const {
        const Layer* layer = layerAt(at.time);
        return layer && layer->holds(at);
    }
    // Calls f(record, weight) for each record of the receiver's instant that holds it (RecordLayer::gather);
    // the weights' sum, 0 where none does.
    template <class F>
    double gather(const Receiver& at, F&& f) const {
        const Layer* layer = layerAt(at.time);
        return layer ? layer->gather(at, f) : 0.0;
    }

    // The requests (taken in their order) that records should be made for now: the first of each region of
    // an instant once as many lookups missed there as `missesToPay` says a record is worth (1 for lookups
    // that wait for it), and none where a record made since covers the point; in the order they came.
    std::vector<RecordRequest> accept(const std::vector<RecordRequest>& requests,
                                      const std::function<int(const RecordRequest&)>& missesToPay) {
        std::vector<std::pair<Layer*, typename Layer::RegionKey>> ready;
        Layer* layer = nullptr;  // the last request's: requests come at one instant, mostly
        double layerKey = 0;
        for (const RecordRequest& q : requests) {
            if (!layer || key(q.at.time) != layerKey) layer = &layerFor(q.at.time), layerKey = key(q.at.time);
            if (auto region = layer->countMiss(q, missesToPay)) ready.push_back({layer, *region});
        }
        std::vector<std::pair<uint64_t, RecordRequest>> accepted;
        for (const auto& [layer, key] : ready)
            if (auto q = layer->takeRegion(key)) accepted.push_back(*q);
        std::stable_sort(accepted.begin(), accepted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<RecordRequest> out;
        for (auto& [order, q] : accepted) out.push_back(q);
        return out;
    }

    // Adds records made here, in their order (each to its instant's layer), for takeUnsaved.
    void insert(std::vector<Record> records) { add(std::move(records), true); }
    // Adds records kept elsewhere (a cache file), in their order.
    void insertSaved(std::vector<Record> records) { add(std::move(records), false); }
    // The records inserted (not insertSaved) since the last call, each instant's in their order.
    std::vector<Record> takeUnsaved() {
        std::vector<Record> out;
        for (auto& [time, layer] : layers_) layer->takeUnsaved(out);
        return out;
    }
    // Forgets the records of every instant but `time` (a sequence that has moved on to it).
    void keepOnly(double time) {
        std::erase_if(layers_, [&](const auto& entry) { return !instants_.keptAt(entry.first, time); });
    }

    // The records of instant `time`, in their order.
    const std::vector<Record>& records(double time) const {
        static const std::vector<Record> kNone;
        const Layer* layer = layerAt(time);
        return layer ? layer->records() : kNone;
    }
    size_t size() const {
        size_t n = 0;
        for (const auto& [time, layer] : layers_) n += layer->records().size();
        return n;
    }
    size_t memoryBytes() const {
        size_t bytes = 0;
        for (const auto& [time, layer] : layers_) bytes += layer->memoryBytes();
        return bytes;
    }
    // "N records (bounce 0: n0, 1: n1, …), M MiB": for progress reports.
    std::string summary() const {
        std::vector<size_t> perLevel;
        for (const auto& [time, layer] : layers_)
            for (const Record& r : layer->records()) {
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

    double key(double time) const { return instants_.of(time); }
    // Few instants are in use at once (a sequence keeps one): a short list, searched from the front.
    const Layer* layerAt(double time) const {
        auto it = std::find_if(layers_.begin(), layers_.end(), [k = key(time)](const auto& e) { return e.first == k; });
        return it == layers_.end() ? nullptr : it->second.get();
    }
    Layer& layerFor(double time) {
        auto it = std::find_if(layers_.begin(), layers_.end(), [k = key(time)](const auto& e) { return e.first == k; });
        if (it != layers_.end()) return *it->second;
        return *layers_.emplace_back(key(time), std::make_unique<Layer>(kind_, origin_)).second;
    }

    void add(std::vector<Record> records, bool unsaved) {
        std::map<double, std::vector<Record>> byInstant;
        for (Record& r : records) byInstant[key(r.time)].push_back(std::move(r));
        for (auto& [time, some] : byInstant) layerFor(time).add(std::move(some), unsaved);
    }

    Kind kind_;
    dvec3 origin_;
    InstantKeys instants_;
    std::vector<std::pair<double, std::unique_ptr<Layer>>> layers_;
};

}  // namespace brume
