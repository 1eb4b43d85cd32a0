// The surface irradiance cache: records of indirect irradiance, found by the zones that hold a point and
// interpolated with METHOD.md's weight; new records are asked for where lookups miss.
//
// Lookups run from any number of threads while no record is added; records are added between such
// passes, in the order the caller gives, so what the cache holds does not depend on the thread count.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cache/irradiance_record.h"
#include "cache/record_shape.h"
#include "geometry/ray.h"

namespace brume {

// Where a lookup found no record: a record could be made here.
struct RecordRequest {
    dvec3 point{0}, normal{0, 0, 1};
    SurfaceId surface;  // the surface under the point, which the record's rays leave
    int level = 0;      // the diffuse bounce of the lookup
    float weight = 1;   // the looking ray's weight (fewer samples for records deep in a path, as Radiance)
    uint64_t key = 0;   // seeds the record's samples: the same request gives the same record
};

class IrradianceCache {
public:
    explicit IrradianceCache(const RecordShape& shape);
    ~IrradianceCache();
    IrradianceCache(const IrradianceCache&) = delete;
    IrradianceCache& operator=(const IrradianceCache&) = delete;

    const RecordShape& shape() const { return shape_; }

    // The irradiance at p (normal n) for a lookup at diffuse bounce `level`, interpolated between the records
    // of that bounce or shallower ones whose zones hold p; false where there are none.
    bool lookup(const dvec3& p, const dvec3& n, int level, Spectrum& irradiance) const;

    // The requests (taken in their order) that records should be made for now: the first of each region
    // of a bounce once as many lookups missed there as `missesToPay` says a record is worth (1 for lookups
    // that wait for it), and none where a record made since covers the point.
    std::vector<RecordRequest> accept(const std::vector<RecordRequest>& requests,
                                      const std::function<int(const RecordRequest&)>& missesToPay);

    // Adds records in their order. Where a new record and an older one of the same bounce disagree by more
    // than the accuracy allows at each other's points, the zones shrink so neither speaks for the other.
    void insert(std::vector<IrradianceRecord> records);

    size_t size() const { return records_.size(); }
    const IrradianceRecord& record(size_t i) const { return records_[i]; }
    size_t memoryBytes() const;
    // "N records (bounce 0: n0, 1: n1, …), M MiB": for progress reports.
    std::string summary() const;

private:
    struct Index;
    struct Found;
    double weigh(const IrradianceRecord& r, const dvec3& p, const dvec3& n, Spectrum* value) const;
    template <class F> void forEachHolding(const dvec3& p, F&& f) const;
    void reconcile(size_t added);
    double regionSize(int level) const;

    RecordShape shape_;
    double cosMaxAngle_;
    std::vector<IrradianceRecord> records_;
    std::unique_ptr<Index> index_;  // a BVH of the zones of records_[0, indexed_)
    size_t indexed_ = 0;
    // Per bounce: the sum of log radii of its records and their count (their typical size sets the regions
    // misses are counted in), and the misses counted per region.
    std::vector<std::pair<double, int>> sizes_;
    struct Region {
        int misses = 0;
        RecordRequest first;
        uint64_t order = 0;  // when the first request arrived
    };
    std::map<std::array<long long, 6>, Region> regions_;
    uint64_t requestsSeen_ = 0;
};

}  // namespace brume
