// Diffuse interreflection from the irradiance cache: lookups, the passes of Integrator::forEach that
// make the records lookups missed, and the records' hemisphere sampling.
#include <numeric>

#include <tbb/parallel_for.h>

#include "cache/hemisphere_samples.h"
#include "cache/record_builder.h"
#include "integrator/path_state.h"

namespace brume {

using namespace integrator_detail;

namespace {
constexpr size_t kRecordsPerRound = 64;  // made together; the next ones may use them
constexpr int kMaxPasses = 24;           // then items take what paths give where records are still missing
constexpr int kMinDivisions = 16;
}  // namespace

Integrator::CacheVisit*& Integrator::currentVisit() {
    thread_local Integrator::CacheVisit* visit = nullptr;
    return visit;
}

// Radiance's radius bounds: the scene's size (its octree's cube, else the box of its extent) over -ar, 64
// times that but at most a fifth of the scene. Records are placed relative to the scene's origin.
RecordShape recordShape(const RenderScene& scene, const RenderSettings& settings) {
    RecordShape shape;
    shape.kind = settings.cacheKind;
    shape.accuracy = settings.ambientAccuracy;
    const Bounds3& box = scene.geometry().extent();
    dvec3 extent = box.empty() ? dvec3(1) : box.hi - box.lo;
    double size = std::max({extent.x, extent.y, extent.z, 1e-6});
    // An octree's cube is Radiance's scale, unless far or huge objects (left out of the extent) made it.
    if (scene.scene().cube && scene.scene().cube->size <= 2 * size) size = scene.scene().cube->size;
    double unit = settings.ambientResolution > 0 ? size / settings.ambientResolution : 0;
    shape.maxRadius = unit > 0 ? std::min(64 * unit, 0.2 * size) : 0.2 * size;
    shape.minRadius = unit > 0 ? unit : shape.maxRadius / 64;
    shape.origin = scene.geometry().origin();
    return shape;
}

std::shared_ptr<IrradianceCache> makeCache(const RenderScene& scene, const RenderSettings& settings) {
    if (settings.ambientBounces <= 0 || !(settings.ambientAccuracy > 0) || settings.ambientDivisions <= 0) return nullptr;
    return std::make_shared<IrradianceCache>(recordShape(scene, settings));
}

// The cached irradiance at the shading point for this side (`normal`). False where the path must sample
// it itself: no cache, or no record here yet — then the record is asked for, and a work item that waits
// for records is marked to run again.
bool Integrator::cachedAmbient(const Shading& sh, const dvec3& normal, const SurfaceId& surface, const Spectrum& coef,
                               const PathState& state, Context& ctx, Spectrum& irradiance) const {
    if (!cache_ || !ctx.visit) return false;
    if (cache_->lookup(sh.point, normal, state.ambientLevel, irradiance)) return true;
    CacheVisit& v = *ctx.visit;
    float weight = float(std::min(1.0, state.weight * std::min(1.0, double(coef.maxValue()))));
    v.requests.push_back({sh.point, normal, surface, state.ambientLevel, weight, mixBits(v.key + ++v.count)});
    if (!v.waits) return false;
    v.missed = true;
    irradiance = Spectrum(0.f);
    return true;
}

// Radiance's -ad at the first bounce, scaled down by the ray's weight deeper in a path.
int Integrator::recordDivisions(const RecordRequest& request) const {
    int ad = settings_.ambientDivisions;
    if (request.level == 0) return ad;
    return std::min(ad, std::max(kMinDivisions, int(ad * request.weight)));
}

void Integrator::forEach(size_t count, const std::function<void(size_t)>& item) const {
    if (!cache_) {
        tbb::parallel_for(size_t(0), count, [&](size_t i) { item(i); });
        return;
    }
    std::vector<size_t> pending(count);
    std::iota(pending.begin(), pending.end(), size_t(0));
    for (int pass = 0; !pending.empty(); ++pass) {
        uint64_t batch = mixBits(runSeed_ ^ (0x51ed270b7a3cULL + passes_++));
        bool last = pass + 1 == kMaxPasses;
        std::vector<CacheVisit> visits(pending.size());
        tbb::parallel_for(size_t(0), pending.size(), [&](size_t p) {
            CacheVisit& v = visits[p];
            v.waits = !last;
            v.key = mixBits(batch ^ pending[p]);
            currentVisit() = &v;
            item(pending[p]);
            currentVisit() = nullptr;
        });
        std::vector<RecordRequest> requests;
        std::vector<size_t> again;
        for (size_t p = 0; p < pending.size(); ++p) {
            if (!visits[p].missed) continue;
            again.push_back(pending[p]);
            requests.insert(requests.end(), visits[p].requests.begin(), visits[p].requests.end());
        }
        makeRecords(requests);
        pending.swap(again);
    }
}

// Makes the records the cache accepts of these requests, a round at a time; the requests of each round's
// own rays (deeper bounces) are served before the next round, so later records use them.
void Integrator::makeRecords(const std::vector<RecordRequest>& requests) const {
    std::vector<RecordRequest> accepted = cache_->accept(requests, [this](const RecordRequest& q) {
        return q.level == 0 ? 1 : std::max(1, recordDivisions(q));
    });
    for (size_t start = 0; start < accepted.size(); start += kRecordsPerRound) {
        size_t n = std::min(kRecordsPerRound, accepted.size() - start);
        std::vector<IrradianceRecord> records(n);
        std::vector<CacheVisit> visits(n);
        tbb::parallel_for(size_t(0), n, [&](size_t i) {
            visits[i].key = accepted[start + i].key;
            records[i] = computeRecord(accepted[start + i], visits[i]);
        });
        cache_->insert(std::move(records));
        std::vector<RecordRequest> deeper;
        for (const CacheVisit& v : visits) deeper.insert(deeper.end(), v.requests.begin(), v.requests.end());
        if (!deeper.empty()) makeRecords(deeper);
    }
}

// A record: the radiance of stratified rays over the hemisphere, each continuing one bounce deeper (where
// the cache, or paths, give the light of further bounces). Sources these rays meet are left out: records
// hold indirect light, next-event estimation gives the direct.
IrradianceRecord Integrator::computeRecord(const RecordRequest& q, CacheVisit& visit) const {
    Context ctx{Random(seedFor(q.key), q.key), nullptr, 0, &visit};
    HemisphereSamples samples(q.point, q.normal, recordDivisions(q), Spectrum::defaultChannels());
    PathState child = startingAt(q.point);
    child.kind = PathState::Kind::Sampled;
    child.ambientLevel = q.level + 1;
    child.reflections = q.level + 1;
    child.weight = q.weight;
    child.from = q.point;
    child.fromWeight = q.weight;
    child.depth = 1;
    for (int j = 0; j < samples.rows(); ++j) {
        for (int k = 0; k < samples.columns(); ++k) {
            dvec3 dir = samples.direction(j, k, ctx.rng.uniform(), ctx.rng.uniform());
            RayRecord hit;
            Spectrum l = radiance(Ray{q.point, dir, std::numeric_limits<double>::infinity(), q.surface}, child, ctx,
                                  &hit, nullptr);
            samples.set(samples.cell(j, k), dir, l.clampFinite(), hit.firstLength);
        }
    }
    return buildRecord(samples, cache_->shape(), q.level);
}

}  // namespace brume
