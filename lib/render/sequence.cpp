#include "render/sequence.h"

#include <algorithm>
#include <numeric>

#include <tbb/parallel_for.h>

#include "integrator/render_options.h"
#include "scene/scene_hash.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr int kMaxPasses = 24;  // then items take what paths give where records are still missing

std::unique_ptr<SurfaceCache> makeCache(const RenderScene& scene, const RenderSettings& settings) {
    if (!settings.usesCache()) return nullptr;
    return std::make_unique<SurfaceCache>(SurfaceZones(recordShape(scene, settings)), scene.geometry().origin());
}

// Only where some medium is (else no volume records, no cost).
std::unique_ptr<VolumeCache> makeVolumeCache(const RenderScene& scene, const RenderSettings& settings) {
    if (!settings.usesCache() || (settings.medium.clear() && !scene.hasMists() && scene.smoke().empty())) return nullptr;
    return std::make_unique<VolumeCache>(VolumeZones(recordShape(scene, settings)), scene.geometry().origin());
}

std::unique_ptr<PersistentCache> openCacheFile(const Scene& scene, const RenderSettings& settings, SurfaceCache* cache,
                                               VolumeCache* volumes) {
    if (settings.cacheFile.empty()) return nullptr;
    if (!cache) {
        warn("-af " + settings.cacheFile + " ignored: there is no irradiance cache without -ab > 0 and -aa > 0");
        return nullptr;
    }
    CacheIdentity identity{sceneContentHash(scene), cacheOptions(settings), Spectrum::defaultChannels()};
    return std::make_unique<PersistentCache>(settings.cacheFile, identity, *cache, volumes);
}

}  // namespace

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
    return shape;
}

Sequence::Sequence(const Scene& scene, const RenderScene& renderScene, const RenderSettings& settings)
    : cache_(makeCache(renderScene, settings)),
      volumes_(makeVolumeCache(renderScene, settings)),
      integrator_(renderScene, settings, cache_.get(), volumes_.get()),
      cacheFile_(openCacheFile(scene, settings, cache_.get(), volumes_.get())),
      scratch_([&renderScene] { return Scratch(renderScene); }) {}

void Sequence::moveTo(double time) {
    integrator_.moveTo(time);
    if (!cache_) return;
    if (!cacheFile_) {  // no file keeps the records made: none waits to be saved
        cache_->takeUnsaved();
        if (volumes_) volumes_->takeUnsaved();
    }
    const double openSince = integrator_.recordWindows().openSince(time);
    cache_->forgetBefore(time, openSince);
    if (volumes_) volumes_->forgetBefore(time, openSince);
}

void Sequence::makeRecords(const std::vector<RecordRequest>& requests) {
    std::vector<RecordRequest> onSurfaces, inMedia;
    for (const RecordRequest& q : requests) (q.at.normal ? onSurfaces : inMedia).push_back(q);
    auto missesToPay = [this](const RecordRequest& q) { return integrator_.missesToPay(q); };
    auto deeper = [this](const std::vector<RecordRequest>& more) { makeRecords(more); };
    const RecordWindows& windows = integrator_.recordWindows();
    if (!onSurfaces.empty())
        tracedRecords_ += brume::makeRecords(
            *cache_, onSurfaces, missesToPay, windows,
            [this](const RecordRequest& q, const OpenRecord<SurfaceRecord>* open, CacheVisit& visit) {
                return integrator_.makeRecords(q, open, scratch_.local(), visit);
            },
            deeper);
    if (!inMedia.empty())
        tracedRecords_ += brume::makeRecords(
            *volumes_, inMedia, missesToPay, windows,
            [this](const RecordRequest& q, const OpenRecord<VolumeRecord>* open, CacheVisit& visit) {
                return integrator_.makeVolumeRecords(q, open, scratch_.local(), visit);
            },
            deeper);
}

void Sequence::run(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item) {
    runPart(count, time, item);
    if (cacheFile_) cacheFile_->sync();
}

void Sequence::runPaths(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item) {
    moveTo(time);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        WorkItem work{scratch_.local()};
        item(i, work);
    });
}

void Sequence::runPart(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item) {
    if (!cache_) return runPaths(count, time, item);
    moveTo(time);
    std::vector<size_t> pending(count);
    std::iota(pending.begin(), pending.end(), size_t(0));
    for (int pass = 0; !pending.empty(); ++pass) {
        uint64_t batch = integrator_.seeds().ofPass(passes_++);
        bool last = pass + 1 == kMaxPasses;
        std::vector<CacheVisit> visits(pending.size());
        tbb::parallel_for(size_t(0), pending.size(), [&](size_t p) {
            CacheVisit& v = visits[p];
            v.waits = !last;
            v.key = mixBits(batch ^ pending[p]);
            WorkItem work{scratch_.local(), &v};
            item(pending[p], work);
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

RenderedPicture Sequence::render(const SequenceFrame& frame, const PictureSettings& settings, ProgressMeter* progress) {
    passes_ = 0;
    RenderedPicture picture = renderPicture(*this, frame.view, frame.time.value_or(0), settings, progress);
    if (cacheFile_) cacheFile_->sync();
    return picture;
}

}  // namespace brume
