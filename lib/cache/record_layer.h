// The records of one kind: found by the zones that hold a receiver (an index of their boxes, and the records
// added since it was built one by one) at the receiver's instant (RecordTime), interpolated by their weights
// in space and time; the misses of lookups counted in regions until they pay for a record; new records
// reconciled with the older ones of their instant.
//
// `Kind` (SurfaceZones, VolumeZones) says how a record speaks for its neighbours: weigh(record, receiver, value*),
// box(record, origin), reach(record), facing(receiver), size(record), sizeBeforeRecords(), reconcile(fresh,
// older); and its Record type, with `point`, `level`, `when` and `values`.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "cache/record_request.h"
#include "cache/record_windows.h"
#include "cache/zone_index.h"
#include "sampling/random.h"
#include "spectrum/spectrum.h"

namespace brume {

template <class Kind>
class RecordLayer {
public:
    using Record = typename Kind::Record;
    // Level, facing, log2 of the size, the region's coordinates, and the instant's bits.
    using RegionKey = std::array<long long, 7>;

    // Regions and the index are measured from `origin` (the scene's): the same records wherever the model
    // stands. `kind` outlives the layer.
    RecordLayer(const Kind& kind, const dvec3& origin)
        : kind_(kind), origin_(origin), beforeRecords_(regionOf(kind.sizeBeforeRecords())) {}
    RecordLayer(const RecordLayer&) = delete;
    RecordLayer& operator=(const RecordLayer&) = delete;

    // The value at the receiver, interpolated between the records of its bounce or shallower ones whose
    // zones hold it; false where there are none.
    bool lookup(const Receiver& at, Spectrum& value) const {
        Spectrum sum(0.f), one(0.f);
        double total = gather(at, [&](const Record&, double w) { sum += one * float(w); }, &one);
        if (!(total > 0)) return false;
        value = sum * float(1 / total);
        return true;
    }
    // Whether a record of the receiver's bounce or shallower holds it.
    bool holds(const Receiver& at) const {
        return gather(at, [](const Record&, double) {}) > 0;
    }
    // Calls f(record, weight) for each record of the receiver's bounce or shallower whose zone holds it at its
    // instant (weight > 0: in space Kind::weigh's, times RecordTime's), its value at the receiver (Kind::weigh's)
    // in `value` first if given; returns the weights' sum.
    template <class F>
    double gather(const Receiver& at, F&& f, Spectrum* value = nullptr) const {
        double total = 0;
        forEachHolding(at.point, [&](size_t i) {
            const Record& r = records_[i];
            if (r.level > at.level) return;
            double inTime = r.when.weightAt(at.time);
            if (!(inTime > 0)) return;
            double w = kind_.weigh(r, at, value) * inTime;
            if (!(w > 0)) return;
            f(r, w);
            total += w;
        });
        return total;
    }

    // Counts a miss of request q in its region (misses at different instants are counted apart): the region's
    // key once as many misses as its first request is worth (`missesToPay` of it) have come.
    template <class Worth>
    std::optional<RegionKey> countMiss(const RecordRequest& q, const Worth& missesToPay) {
        const RegionSize& region = regionSize(q.at.level);
        double size = region.size;
        dvec3 p = q.at.point - origin_;
        RegionKey key{q.at.level,           kind_.facing(q.at),     region.log2,
                      regionIndex(p.x, size), regionIndex(p.y, size), regionIndex(p.z, size),
                      std::bit_cast<long long>(q.at.time)};
        Region& counted = regions_[key];
        if (counted.misses++ == 0) counted.first = q, counted.order = requestsSeen_;
        ++requestsSeen_;
        if (counted.misses == missesToPay(counted.first)) return key;
        return std::nullopt;
    }
    // The first request of a region that has paid (with when it came), unless a record made since covers
    // its point; the region counts afresh after.
    std::optional<std::pair<uint64_t, RecordRequest>> takeRegion(const RegionKey& key) {
        auto it = regions_.find(key);
        std::optional<std::pair<uint64_t, RecordRequest>> out;
        if (!holds(it->second.first.at)) out.emplace(it->second.order, it->second.first);
        regions_.erase(it);
        return out;
    }

    // Adds records in their order, each reconciled with the older ones of its bounce; `unsaved`: made here,
    // to be handed to takeUnsaved. `opened[i]`, where given, is the request a window from record i may
    // re-trace (RecordWindows): record i is open.
    void add(std::vector<Record> records, bool unsaved, std::vector<std::optional<RecordRequest>> opened = {}) {
        size_t before = records_.size();
        opened.resize(records.size());
        for (size_t k = 0; k < records.size(); ++k) {
            countSize(records[k]);
            if (unsaved) unsaved_.push_back(records_.size());
            records_.push_back(std::move(records[k]));
            opened_.push_back(std::move(opened[k]));
            reconcile(records_.size() - 1);
        }
        size_t indexed = index_.size();
        if (records_.size() - indexed <= std::max(kUnindexedLimit, indexed / 8) && before > 0) return;
        buildIndex();
    }
    // Forgets the records whose window is over at instant t, but for open ones of instants from `openSince`
    // on, and the misses counted before t: a run that has moved on to t. Those not yet handed to takeUnsaved
    // still will be. The regions are sized by the records kept.
    void forgetBefore(double t, double openSince) {
        std::erase_if(regions_, [t](const auto& entry) { return entry.second.first.at.time < t; });
        std::vector<bool> unsaved(records_.size());
        for (size_t i : unsaved_) unsaved[i] = true;
        auto forgotten = [&](size_t i) {
            return records_[i].when.overAt(t) && !(opened_[i] && records_[i].when.at >= openSince);
        };
        size_t i = 0;
        while (i < records_.size() && !forgotten(i)) ++i;
        if (i == records_.size()) return;
        std::vector<Record> kept;
        std::vector<std::optional<RecordRequest>> keptOpened;
        std::vector<size_t> keptUnsaved;
        for (i = 0; i < records_.size(); ++i) {
            if (forgotten(i)) {
                if (unsaved[i]) forgottenUnsaved_.push_back(std::move(records_[i]));
                continue;
            }
            if (unsaved[i]) keptUnsaved.push_back(kept.size());
            kept.push_back(std::move(records_[i]));
            keptOpened.push_back(std::move(opened_[i]));
        }
        records_ = std::move(kept);
        opened_ = std::move(keptOpened);
        unsaved_ = std::move(keptUnsaved);
        sizes_.clear();
        for (const Record& r : records_) countSize(r);
        buildIndex();
    }
    // Appends the records added as unsaved since the last call to `out`, in their order (those forgotten
    // since first).
    void takeUnsaved(std::vector<Record>& out) {
        std::move(forgottenUnsaved_.begin(), forgottenUnsaved_.end(), std::back_inserter(out));
        forgottenUnsaved_.clear();
        for (size_t i : unsaved_) out.push_back(records_[i]);
        unsaved_.clear();
    }

    // The open record (RecordWindows) a window serving the request's instant may start from: of its bounce,
    // its zone holding the point, reaching its instant (windows.reaches); the latest, then the one weighing
    // most, then the first. None where there is none.
    std::optional<size_t> openFor(const Receiver& at, const RecordWindows& windows) const {
        std::optional<size_t> best;
        double bestAt = 0, bestWeight = 0;
        forEachHolding(at.point, [&](size_t i) {
            const Record& r = records_[i];
            if (!opened_[i] || r.level != at.level || !windows.reaches(r.when.at, at.time)) return;
            double w = kind_.weigh(r, at, nullptr);
            if (!(w > 0)) return;
            bool better = !best || r.when.at > bestAt || (r.when.at == bestAt && (w > bestWeight || (w == bestWeight && i < *best)));
            if (better) best = i, bestAt = r.when.at, bestWeight = w;
        });
        return best;
    }
    // Open record i and the request it was made for.
    OpenRecord<Record> open(size_t i) const { return {records_[i], *opened_[i]}; }
    // Closes open record i: a window has started from it.
    void close(size_t i) { opened_[i].reset(); }

    const std::vector<Record>& records() const { return records_; }
    size_t memoryBytes() const {
        size_t bytes = records_.capacity() * sizeof(Record) + opened_.capacity() * sizeof(opened_[0]) +
                       regions_.size() * (sizeof(Region) + 64);
        for (const Record& r : records_) bytes += r.heapBytes();
        return bytes;
    }

private:
    struct Region {
        int misses = 0;
        RecordRequest first;
        uint64_t order = 0;  // when the first request arrived
    };
    // Records added since the index was built are looked at one by one; it is rebuilt when they are more
    // than this, or an eighth of the indexed ones (so rebuilding costs a constant factor of the records' count).
    static constexpr size_t kUnindexedLimit = 64;

    // Calls f(i) for every record whose zone's box holds p.
    template <class F>
    void forEachHolding(const dvec3& p, F&& f) const {
        index_.forEachHolding(p - origin_, f);
        for (size_t i = index_.size(); i < records_.size(); ++i) {
            dvec3 d = p - records_[i].point;
            double reach = kind_.reach(records_[i]);
            if (glm::dot(d, d) <= reach * reach) f(i);
        }
    }

    // Counts the record's size in its bounce's typical size (the regions misses are counted in).
    void countSize(const Record& r) {
        if (sizes_.size() <= size_t(r.level)) sizes_.resize(r.level + 1);
        LevelSizes& level = sizes_[r.level];
        level.logSum += std::log(kind_.size(r));
        ++level.count;
        level.region = regionOf(std::exp(level.logSum / level.count));
    }
    void buildIndex() {
        std::vector<ZoneBox> boxes;
        boxes.reserve(records_.size());
        for (const Record& r : records_) boxes.push_back(kind_.box(r, origin_));
        index_.build(boxes);
    }

    // Records of one bounce and one instant check each other's light; those of other instants hold other light.
    void reconcile(size_t added) {
        Record& fresh = records_[added];
        forEachHolding(fresh.point, [&](size_t i) {
            if (i == added || records_[i].level != fresh.level || records_[i].when.at != fresh.when.at) return;
            kind_.reconcile(fresh, records_[i]);
        });
    }

    // Regions where misses are counted: cubes twice the typical record's size at that bounce (a power of
    // two, so that they stay put while the typical size drifts).
    struct RegionSize {
        double size;
        long long log2;
    };
    static RegionSize regionOf(double typical) {
        double size = std::exp2(std::round(std::log2(2 * typical)));
        return {size, std::llround(std::log2(size))};
    }
    const RegionSize& regionSize(int level) const {
        return size_t(level) < sizes_.size() && sizes_[level].count > 0 ? sizes_[level].region : beforeRecords_;
    }
    struct KeyHash {
        size_t operator()(const RegionKey& k) const {
            uint64_t h = 0;
            for (long long x : k) h = mixBits(h ^ uint64_t(x));
            return size_t(h);
        }
    };

    // The region of coordinate x along one axis, for regions `size` wide. Coordinates so far out that the
    // index would not fit a long long (a sensor at 1e300) share the outermost region on their side:
    // converting them unclamped is undefined, and on x86 put both sides in one region.
    static long long regionIndex(double x, double size) {
        constexpr double kOutermost = 0x1p62;
        return (long long)std::clamp(std::floor(x / size), -kOutermost, kOutermost);
    }

    const Kind& kind_;
    dvec3 origin_;
    std::vector<Record> records_;
    std::vector<std::optional<RecordRequest>> opened_;  // per record: the request a window from it re-traces
    ZoneIndex index_;  // over the zones of records_[0, index_.size())
    std::vector<size_t> unsaved_;
    std::vector<Record> forgottenUnsaved_;  // forgotten before takeUnsaved handed them out
    // Per bounce: the sum of the log sizes of its records, their count, and the size of the regions misses
    // are counted in that the records' typical size gives; the misses counted per region.
    struct LevelSizes {
        double logSum = 0;
        int count = 0;
        RegionSize region{};
    };
    std::vector<LevelSizes> sizes_;
    RegionSize beforeRecords_;
    std::unordered_map<RegionKey, Region, KeyHash> regions_;
    uint64_t requestsSeen_ = 0;
};

}  // namespace brume
