// The irradiance cache as light transport uses it: lookups at diffuse shading points (noting the records they
// miss), and the hemisphere of rays a record is made of.
#pragma once
#include "cache/surface_cache.h"
#include "integrator/hit_shading.h"
#include "integrator/media.h"
#include "integrator/settings.h"
#include "integrator/tracer.h"

namespace brume {

class CacheClient {
public:
    // `cache` may be null (no cache: -ab or -aa 0); `seeds` seed the records' rays by their requests' keys.
    CacheClient(const SurfaceCache* cache, const RenderSettings& settings, const Tracer& tracer,
                const HitShading& shading, const Media& media, Seeds seeds)
        : cache_(cache), settings_(settings), tracer_(tracer), shading_(shading), media_(media), seeds_(seeds) {}

    const SurfaceCache* cache() const { return cache_; }
    // The indirect irradiance at a diffuse shading point from the records (true). Where there is none, the
    // work item's visit asks for one (a ray of weight `weight` missed it) and the path samples the light
    // itself (false) — unless the item waits for the record: then true with 0, the item running again.
    bool irradiance(const Receiver& at, const SurfaceId& surface, float weight, PathContext& ctx, Spectrum& value) const;

    // Radiance's -ad at the first bounce, scaled down by the looking ray's weight deeper in a path.
    int recordDivisions(const RecordRequest& request) const;
    // A record: the radiance of stratified rays over the hemisphere, each continuing one bounce deeper (where
    // the cache, or paths, give the light of further bounces). Sources these rays meet are left out: records
    // hold indirect light, next-event estimation gives the direct. Their own misses go to `visit`.
    SurfaceRecord makeRecord(const RecordRequest& request, Scratch& scratch, CacheVisit& visit) const;

private:
    const SurfaceCache* cache_;
    const RenderSettings& settings_;
    const Tracer& tracer_;
    const HitShading& shading_;
    const Media& media_;
    Seeds seeds_;
};

}  // namespace brume
