#include "cache/irradiance_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <embree3/rtcore.h>

namespace brume {

namespace {
// Records added since the BVH was built are looked at one by one; it is rebuilt when they are more than
// this, or an eighth of the indexed ones (so rebuilding costs a constant factor of the records' count).
constexpr size_t kUnindexedLimit = 64;
}

// Embree's BVH over the records' zones, asked with point queries (radius 0: the zones' boxes holding a point).
struct IrradianceCache::Index {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = nullptr;
    ~Index() {
        if (scene) rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

// What a point query calls for each record it finds.
struct IrradianceCache::Found {
    void* f;
    void (*call)(void*, size_t);
};

IrradianceCache::IrradianceCache(const RecordShape& shape)
    : shape_(shape), cosMaxAngle_(std::cos(shape.maxAngle())), index_(std::make_unique<Index>()) {}

IrradianceCache::~IrradianceCache() = default;

// Where p lies in the record's zone: 0 at its point, 1 on its edge (or beyond, or -1 far behind its plane:
// a crease). Off the plane counts like distance along the short axis. Also p's coordinates along k1, k2.
static double zoneDistance(const IrradianceRecord& r, const dvec3& p, double& a, double& b) {
    dvec3 delta = p - r.point;
    double h = glm::dot(delta, r.normal);
    if (h < -0.1 * r.radius[0]) return -1;
    a = glm::dot(delta, r.axis), b = glm::dot(delta, r.axis2());
    double qa = a / r.radius[0], qb = b / r.radius[1], qh = h / r.radius[0];
    return std::sqrt(qa * qa + qb * qb + qh * qh);
}

// The record's weight at (p, n), 0 outside its zone: (|RP'|/|RP| − 1)(1 − α/α_max), P' where the ray from
// the record through p leaves the ellipse. With `value`, also its extrapolation to (p, n).
double IrradianceCache::weigh(const IrradianceRecord& r, const dvec3& p, const dvec3& n, Spectrum* value) const {
    double cosAlpha = glm::dot(n, r.normal);
    if (cosAlpha <= cosMaxAngle_) return 0;
    double a = 0, b = 0, q = zoneDistance(r, p, a, b);
    if (q < 0 || q >= 1) return 0;
    double alpha = std::acos(std::min(1.0, cosAlpha));
    double w = (q < 1e-6 ? 1e6 : 1 / q - 1) * (1 - alpha / shape_.maxAngle());
    if (!(w > 0)) return 0;
    if (value) {
        dvec3 tilt = n - r.normal;
        double t1 = glm::dot(tilt, r.axis), t2 = glm::dot(tilt, r.axis2());
        bool secondOrder = shape_.kind == RecordShape::Kind::Adaptive;
        const int ch = r.channels();
        *value = Spectrum(0.f, ch);
        for (int c = 0; c < ch; ++c) {
            double e = r.value(IrradianceRecord::kIrradiance, c);
            double change = r.value(IrradianceRecord::kAlongK1, c) * a + r.value(IrradianceRecord::kAlongK2, c) * b +
                            r.value(IrradianceRecord::kTiltK1, c) * t1 + r.value(IrradianceRecord::kTiltK2, c) * t2;
            if (secondOrder) change -= 0.5 * e * alpha * alpha;
            (*value)[c] = float(e + std::clamp(change, -e, e));
        }
    }
    return w;
}

// Calls f(i) for every record whose zone's box holds p.
template <class F>
void IrradianceCache::forEachHolding(const dvec3& p, F&& f) const {
    if (index_->scene && indexed_ > 0) {
        Found found{&f, [](void* g, size_t i) { (*static_cast<std::remove_reference_t<F>*>(g))(i); }};
        RTCPointQuery query;
        dvec3 q = p - shape_.origin;
        query.x = float(q.x), query.y = float(q.y), query.z = float(q.z);
        query.time = 0, query.radius = 0;
        RTCPointQueryContext context;
        rtcInitPointQueryContext(&context);
        rtcPointQuery(index_->scene, &query, &context,
                      [](RTCPointQueryFunctionArguments* args) {
                          auto* found = static_cast<Found*>(args->userPtr);
                          found->call(found->f, args->primID);
                          return false;
                      },
                      &found);
    }
    for (size_t i = indexed_; i < records_.size(); ++i) {
        const IrradianceRecord& r = records_[i];
        dvec3 d = p - r.point;
        double reach = std::max(r.radius[0], r.radius[1]);
        if (glm::dot(d, d) <= reach * reach) f(i);
    }
}

bool IrradianceCache::lookup(const dvec3& p, const dvec3& n, int level, Spectrum& irradiance) const {
    double total = 0;
    Spectrum sum(0.f), value(0.f);
    forEachHolding(p, [&](size_t i) {
        const IrradianceRecord& r = records_[i];
        if (r.level > level) return;
        double w = weigh(r, p, n, &value);
        if (w <= 0) return;
        sum += value * float(w);
        total += w;
    });
    if (!(total > 0)) return false;
    irradiance = sum * float(1 / total);
    return true;
}

size_t IrradianceCache::memoryBytes() const {
    size_t bytes = records_.capacity() * sizeof(IrradianceRecord);
    for (const IrradianceRecord& r : records_) bytes += r.values.capacity() * sizeof(float);
    return bytes + regions_.size() * (sizeof(Region) + 64);
}

std::string IrradianceCache::summary() const {
    std::vector<size_t> perLevel;
    for (const IrradianceRecord& r : records_) {
        if (perLevel.size() <= size_t(r.level)) perLevel.resize(r.level + 1);
        ++perLevel[r.level];
    }
    std::string text = std::to_string(records_.size()) + " records (bounce";
    for (size_t l = 0; l < perLevel.size(); ++l)
        text += (l ? ", " : " ") + std::to_string(l) + ": " + std::to_string(perLevel[l]);
    char memory[32];
    std::snprintf(memory, sizeof memory, "), %.1f MiB", memoryBytes() / 1048576.0);
    return text + memory;
}

// Regions where misses are counted: cubes twice the typical record's short radius at that bounce (a power
// of two, so the regions stay put while the typical size drifts), per dominant normal direction.
double IrradianceCache::regionSize(int level) const {
    double typical = shape_.kind == RecordShape::Kind::Classic ? shape_.accuracy * shape_.maxRadius / 4
                                                               : shape_.maxRadius / 4;
    if (size_t(level) < sizes_.size() && sizes_[level].second > 0)
        typical = std::exp(sizes_[level].first / sizes_[level].second);
    return std::exp2(std::round(std::log2(2 * typical)));
}

namespace {
// The region of coordinate x along one axis, for regions `size` wide. Coordinates so far out that the index
// would not fit a long long (a sensor at 1e300) share the outermost region on their side: converting them
// unclamped is undefined, and on x86 put both sides in one region.
long long regionIndex(double x, double size) {
    constexpr double kOutermost = 0x1p62;
    return (long long)std::clamp(std::floor(x / size), -kOutermost, kOutermost);
}
}  // namespace

std::vector<RecordRequest> IrradianceCache::accept(const std::vector<RecordRequest>& requests,
                                                   const std::function<int(const RecordRequest&)>& missesToPay) {
    std::vector<std::array<long long, 6>> ready;
    for (const RecordRequest& q : requests) {
        double size = regionSize(q.level);
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(q.normal[k]) > std::abs(q.normal[axis])) axis = k;
        dvec3 p = q.point - shape_.origin;
        std::array<long long, 6> key{q.level, axis * 2 + (q.normal[axis] < 0), std::llround(std::log2(size)),
                                     regionIndex(p.x, size), regionIndex(p.y, size), regionIndex(p.z, size)};
        Region& region = regions_[key];
        if (region.misses++ == 0) region.first = q, region.order = requestsSeen_;
        ++requestsSeen_;
        if (region.misses == missesToPay(region.first)) ready.push_back(key);
    }
    std::vector<std::pair<uint64_t, RecordRequest>> accepted;
    Spectrum unused;
    for (const auto& key : ready) {
        auto it = regions_.find(key);
        const RecordRequest& q = it->second.first;
        if (!lookup(q.point, q.normal, q.level, unused)) accepted.push_back({it->second.order, q});
        regions_.erase(it);
    }
    std::sort(accepted.begin(), accepted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<RecordRequest> out;
    for (auto& [order, q] : accepted) out.push_back(q);
    return out;
}

void IrradianceCache::insert(std::vector<IrradianceRecord> records) {
    size_t before = records_.size();
    for (IrradianceRecord& r : records) {
        if (sizes_.size() <= size_t(r.level)) sizes_.resize(r.level + 1);
        sizes_[r.level].first += std::log(double(r.radius[0]));
        ++sizes_[r.level].second;
        records_.push_back(std::move(r));
        reconcile(records_.size() - 1);
    }
    if (records_.size() - indexed_ <= std::max(kUnindexedLimit, indexed_ / 8) && before > 0) return;
    if (index_->scene) rtcReleaseScene(index_->scene);
    index_->scene = rtcNewScene(index_->device);
    RTCGeometry geometry = rtcNewGeometry(index_->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(records_.size()));
    rtcSetGeometryUserData(geometry, this);
    rtcSetGeometryBoundsFunction(
        geometry,
        [](const RTCBoundsFunctionArguments* args) {
            const auto& cache = *static_cast<const IrradianceCache*>(args->geometryUserPtr);
            const IrradianceRecord& r = cache.records_[args->primID];
            // The zone is within the ellipsoid of semi-axes r0 (k1 and the normal) and r1 (k2): its box.
            dvec3 k1 = r.axis * double(r.radius[0]), k2 = r.axis2() * double(r.radius[1]), n = r.normal * double(r.radius[0]);
            dvec3 p = r.point - cache.shape_.origin;
            dvec3 reach = glm::sqrt(k1 * k1 + k2 * k2 + n * n) * 1.001 + 1e-6 * glm::length(p);
            args->bounds_o->lower_x = float(p.x - reach.x), args->bounds_o->upper_x = float(p.x + reach.x);
            args->bounds_o->lower_y = float(p.y - reach.y), args->bounds_o->upper_y = float(p.y + reach.y);
            args->bounds_o->lower_z = float(p.z - reach.z), args->bounds_o->upper_z = float(p.z + reach.z);
        },
        nullptr);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(index_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(index_->scene);
    indexed_ = records_.size();
}

// Splotch control: the new record and each older record of its bounce must agree, within twice the
// accuracy, at each other's points where their zones hold them; else the zone that holds the other shrinks
// to leave it out (by at most half at a time: one of the two may be the noisy one).
void IrradianceCache::reconcile(size_t added) {
    IrradianceRecord& fresh = records_[added];
    const double tolerance = 2 * shape_.accuracy;
    Spectrum value(0.f);
    auto shrinkToExclude = [&](IrradianceRecord& holder, const IrradianceRecord& other) {
        if (weigh(holder, other.point, other.normal, &value) <= 0) return;
        double seen = brightness(value), actual = brightness(other.field(IrradianceRecord::kIrradiance));
        if (std::abs(seen - actual) <= tolerance * std::max(seen, actual)) return;
        double a, b;
        float factor = float(std::max(0.5, 0.999 * zoneDistance(holder, other.point, a, b)));
        holder.radius[0] *= factor, holder.radius[1] *= factor;
    };
    forEachHolding(fresh.point, [&](size_t i) {
        if (i == added || records_[i].level != fresh.level) return;
        shrinkToExclude(records_[i], fresh);
        shrinkToExclude(fresh, records_[i]);
    });
}

}  // namespace brume
