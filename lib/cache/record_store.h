// The records of one kind (surface records now; volume records next) at the instants in use, each instant's
// indexed by their zones; found by the zones that hold a receiver and interpolated by their weights; new
// records asked for where lookups miss.
//
// `Kind` (SurfaceZones) says how a record speaks for its neighbours: weigh(record, receiver, value*),
// box(record, origin), reach(record), facing(receiver), size(record), sizeBeforeRecords(), reconcile(fresh,
// older), and its Record type, with `point`, `level` and `time`.
//
// Lookups run from any number of threads while no record is added; records are added between such passes,
// in the order the caller gives, so what the store holds does not depend on the thread count. Where the scene
// changes in time (`timed`), a record holds the light of its own instant only: each instant's records are
// kept, indexed and counted apart, as if in a store of their own.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "cache/record_request.h"
#include "cache/zone_index.h"
#include "spectrum/spectrum.h"

namespace brume {

template <class Kind>
class RecordStore {
public:
    using Record = typename Kind::Record;

    // Regions and the index are measured from `origin` (the scene's): the same records wherever the model
    // stands.
    RecordStore(Kind kind, const dvec3& origin, bool timed) : kind_(std::move(kind)), origin_(origin), timed_(timed) {}
    RecordStore(const RecordStore&) = delete;
    RecordStore& operator=(const RecordStore&) = delete;

    const Kind& kind() const { return kind_; }
    bool timed() const { return timed_; }

    // The value at the receiver, interpolated between the records of its instant and of its bounce or
    // shallower ones whose zones hold it; false where there are none.
    bool lookup(const Receiver& at, Spectrum& value) const {
        const Layer* layer = layerAt(at.time);
        if (!layer) return false;
        double total = 0;
        Spectrum sum(0.f), one(0.f);
        layer->forEachHolding(at.point, [&](size_t i) {
            const Record& r = layer->records[i];
            if (r.level > at.level) return;
            double w = kind_.weigh(r, at, &one);
            if (w <= 0) return;
            sum += one * float(w);
            total += w;
        }, kind_, origin_);
        if (!(total > 0)) return false;
        value = sum * float(1 / total);
        return true;
    }

    // The requests (taken in their order) that records should be made for now: the first of each region of
    // an instant and bounce once as many lookups missed there as `missesToPay` says a record is worth (1 for
    // lookups that wait for it), and none where a record made since covers the point. Regions are cubes
    // twice the typical record's size at that bounce (a power of two, so they stay put while the typical size
    // drifts), apart for receivers facing different ways.
    std::vector<RecordRequest> accept(const std::vector<RecordRequest>& requests,
                                      const std::function<int(const RecordRequest&)>& missesToPay) {
        std::vector<std::pair<Layer*, RegionKey>> ready;
        for (const RecordRequest& q : requests) {
            Layer& layer = layerFor(q.at.time);
            double size = regionSize(layer, q.at.level);
            dvec3 p = q.at.point - origin_;
            RegionKey key{q.at.level, kind_.facing(q.at), std::llround(std::log2(size)), regionIndex(p.x, size),
                          regionIndex(p.y, size), regionIndex(p.z, size)};
            Region& region = layer.regions[key];
            if (region.misses++ == 0) region.first = q, region.order = layer.requestsSeen;
            ++layer.requestsSeen;
            if (region.misses == missesToPay(region.first)) ready.push_back({&layer, key});
        }
        std::vector<std::pair<uint64_t, RecordRequest>> accepted;
        Spectrum unused;
        for (const auto& [layer, key] : ready) {
            auto it = layer->regions.find(key);
            const RecordRequest& q = it->second.first;
            if (!lookup(q.at, unused)) accepted.push_back({it->second.order, q});
            layer->regions.erase(it);
        }
        std::stable_sort(accepted.begin(), accepted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<RecordRequest> out;
        for (auto& [order, q] : accepted) out.push_back(q);
        return out;
    }

    // Adds records made here, in their order: they are reconciled with the older ones of their instant and
    // bounce (Kind::reconcile), and kept for takeUnsaved.
    void insert(std::vector<Record> records) { add(std::move(records), true); }
    // Adds records kept elsewhere (a cache file), in their order.
    void insertSaved(std::vector<Record> records) { add(std::move(records), false); }
    // The records inserted (not insertSaved) since the last call, each instant's in their order.
    std::vector<Record> takeUnsaved() {
        std::vector<Record> out;
        for (auto& [time, layer] : layers_) {
            for (size_t i : layer.unsaved) out.push_back(layer.records[i]);
            layer.unsaved.clear();
        }
        return out;
    }
    // Forgets the records of every instant but `time` (a sequence that has moved on to it).
    void keepOnly(double time) {
        if (!timed_) return;
        std::erase_if(layers_, [&](const auto& entry) { return entry.first != time; });
    }

    size_t size() const {
        size_t n = 0;
        for (const auto& [time, layer] : layers_) n += layer.records.size();
        return n;
    }
    // The records of the receiver's instant, in their order.
    const std::vector<Record>& records(double time) const {
        static const std::vector<Record> kNone;
        const Layer* layer = layerAt(time);
        return layer ? layer->records : kNone;
    }
    size_t memoryBytes() const {
        size_t bytes = 0;
        for (const auto& [time, layer] : layers_) {
            bytes += layer.records.capacity() * sizeof(Record) + layer.regions.size() * (sizeof(Region) + 64);
            for (const Record& r : layer.records) bytes += r.values.capacity() * sizeof(float);
        }
        return bytes;
    }
    // "N records (bounce 0: n0, 1: n1, …), M MiB": for progress reports.
    std::string summary() const {
        std::vector<size_t> perLevel;
        for (const auto& [time, layer] : layers_)
            for (const Record& r : layer.records) {
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
    // Level, facing, log2 of the size, and the region's coordinates.
    using RegionKey = std::array<long long, 6>;
    struct Region {
        int misses = 0;
        RecordRequest first;
        uint64_t order = 0;  // when the first request arrived
    };
    // One instant's records and what finding and placing them needs.
    struct Layer {
        std::vector<Record> records;
        ZoneIndex index;          // over the zones of records[0, index.size())
        std::vector<ZoneBox> boxes;
        std::vector<size_t> unsaved;
        // Per bounce: the sum of the log sizes of its records and their count (their typical size sets the
        // regions misses are counted in), and the misses counted per region.
        std::vector<std::pair<double, int>> sizes;
        std::map<RegionKey, Region> regions;
        uint64_t requestsSeen = 0;

        // Calls f(i) for every record whose zone's box holds p; records added since the index was built are
        // tested one by one, by their reach.
        template <class F>
        void forEachHolding(const dvec3& p, F&& f, const Kind& kind, const dvec3& origin) const {
            index.forEachHolding(p - origin, f);
            for (size_t i = index.size(); i < records.size(); ++i) {
                dvec3 d = p - records[i].point;
                double reach = kind.reach(records[i]);
                if (glm::dot(d, d) <= reach * reach) f(i);
            }
        }
    };
    // Records added since the index was built are looked at one by one; it is rebuilt when they are more
    // than this, or an eighth of the indexed ones (so rebuilding costs a constant factor of the records' count).
    static constexpr size_t kUnindexedLimit = 64;

    double key(double time) const { return timed_ ? time : 0.0; }
    const Layer* layerAt(double time) const {
        auto it = layers_.find(key(time));
        return it == layers_.end() ? nullptr : &it->second;
    }
    Layer& layerFor(double time) { return layers_[key(time)]; }

    double regionSize(const Layer& layer, int level) const {
        double typical = kind_.sizeBeforeRecords();
        if (size_t(level) < layer.sizes.size() && layer.sizes[level].second > 0)
            typical = std::exp(layer.sizes[level].first / layer.sizes[level].second);
        return std::exp2(std::round(std::log2(2 * typical)));
    }

    // The region of coordinate x along one axis, for regions `size` wide. Coordinates so far out that the
    // index would not fit a long long (a sensor at 1e300) share the outermost region on their side:
    // converting them unclamped is undefined, and on x86 put both sides in one region.
    static long long regionIndex(double x, double size) {
        constexpr double kOutermost = 0x1p62;
        return (long long)std::clamp(std::floor(x / size), -kOutermost, kOutermost);
    }

    void add(std::vector<Record> records, bool unsaved) {
        std::map<double, std::vector<Record>> byInstant;
        for (Record& r : records) byInstant[key(r.time)].push_back(std::move(r));
        for (auto& [time, some] : byInstant) addTo(layers_[time], std::move(some), unsaved);
    }

    void addTo(Layer& layer, std::vector<Record> records, bool unsaved) {
        size_t before = layer.records.size();
        for (Record& r : records) {
            if (layer.sizes.size() <= size_t(r.level)) layer.sizes.resize(r.level + 1);
            layer.sizes[r.level].first += std::log(kind_.size(r));
            ++layer.sizes[r.level].second;
            if (unsaved) layer.unsaved.push_back(layer.records.size());
            layer.records.push_back(std::move(r));
            reconcile(layer, layer.records.size() - 1);
        }
        size_t indexed = layer.index.size();
        if (layer.records.size() - indexed <= std::max(kUnindexedLimit, indexed / 8) && before > 0) return;
        layer.boxes.clear();
        for (const Record& r : layer.records) layer.boxes.push_back(kind_.box(r, origin_));
        layer.index.build(layer.boxes);
    }

    void reconcile(Layer& layer, size_t added) {
        Record& fresh = layer.records[added];
        layer.forEachHolding(fresh.point, [&](size_t i) {
            if (i == added || layer.records[i].level != fresh.level) return;
            kind_.reconcile(fresh, layer.records[i]);
        }, kind_, origin_);
    }

    Kind kind_;
    dvec3 origin_;
    bool timed_;
    std::map<double, Layer> layers_;
};

}  // namespace brume
