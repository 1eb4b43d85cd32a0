// Radiance values along rays, as Radiance's rtrace defines them, computed without bias: next-event
// estimation of every source with multiple importance sampling, diffuse interreflection from the irradiance
// cache or by path tracing (-ad paths at the first bounce, one after it, -ab bounces), specular and glossy
// rays, participating media, Russian roulette.
//
// The Integrator answers one ray at a time, and is the Tracer its parts spawn rays through: what shades a
// hit (HitShading), next-event estimation (LightSampler), the lobes of a surface (SurfaceScattering), media
// (MediaTransport), the irradiance cache (CacheClient). Loops over many rays (lib/render's Sequence) give it
// each work item's scratch and cache visit.
#pragma once
#include <memory>

#include "cache/surface_cache.h"
#include "integrator/cache_client.h"
#include "integrator/contributions.h"
#include "integrator/deferred_bounces.h"
#include "integrator/hit_shading.h"
#include "integrator/light_sampler.h"
#include "integrator/media.h"
#include "integrator/media_transport.h"
#include "integrator/settings.h"
#include "integrator/shadow_rays.h"
#include "integrator/sky_portals.h"
#include "integrator/sun_patches.h"
#include "integrator/surface_scattering.h"
#include "integrator/tracer.h"
#include "io/ray_record.h"

namespace brume {

// A ray, a pixel's ray or a sensor that a program asks about.
struct RayQuery {
    dvec3 org, dir;          // for a sensor: its point and the normal of its surface
    uint64_t index = 0;      // seeds its samples
    double time = 0;         // the scene's instant (s): one the integrator has prepared
    double maxDistance = 0;  // > 0: how far the ray looks (rtrace -ld, a view's aft clipping plane)
};

// What one work item of a loop over many gives the integrator: its thread's scratch and, with the cache,
// where its lookups note the records they miss (none: no lookups, paths sample what records would give);
// and where its sources' contributions go (contributions.h: without the cache and media only), if asked.
struct WorkItem {
    Scratch& scratch;
    CacheVisit* visit = nullptr;
    ContributionSink* contributions = nullptr;
    BounceSink* bounces = nullptr;  // where first bounces defer their continuations (without the cache and media)
};

class Integrator final : public Tracer {
public:
    // `cache`, `volumes`: the irradiance caches to look records up in (null: none); they outlive the
    // integrator. Error where the settings' instant (-T) is outside the smoke's key frames.
    Integrator(const RenderScene& scene, const RenderSettings& settings, const SurfaceCache* cache = nullptr,
               const VolumeCache* volumes = nullptr);

    // The instants its rays are traced at (their smoke, the span with data).
    const Instants& instants() const { return instants_; }
    // Forgets the smoke of the instants no record made from now on is traced at: those before the earliest a
    // window serving `time` may start from (RecordWindows::openSince). Not while rays are traced.
    void moveTo(double time) { instants_.forgetBefore(recordWindows().openSince(time)); }

    // Radiance arriving at q.org from direction q.dir (the ray's value), and rtrace's other outputs of the
    // ray; `tree`, if given, receives every ray traced for it.
    RayRecord trace(const RayQuery& q, WorkItem& item, RayTree* tree = nullptr) const;
    // Irradiance at point q.org on a surface facing q.dir (rtrace -I): that of a white Lambertian sensor.
    RayRecord irradiance(const RayQuery& q, WorkItem& item, RayTree* tree = nullptr) const;
    // Irradiance at the first opaque surface the ray meets; light sources give their radiance (rtrace -i).
    RayRecord irradianceAtHit(const RayQuery& q, WorkItem& item, RayTree* tree = nullptr) const;

    // The radiance the continuation of a deferred bounce brings back along unit `dir` (in its hemisphere), its
    // sources' contributions told to item.contributions; `weightScale` multiplies its weight (the bounces it
    // stands for), `index` seeds its samples.
    Spectrum continueBounce(const DeferredBounce& bounce, const dvec3& dir, double time, double weightScale,
                            uint64_t index, WorkItem& item) const;
    // ∫K of every medium on the straight line from `from` to `to` (the global one, the mists around `from`, the
    // smoke at `time`, a prepared instant), surfaces ignored and exact, K each medium's as a study quotes one
    // number (QuotedExtinction): the optical depth of a line of sight, for Jin's law.
    double quotedDepthBetween(const dvec3& from, const dvec3& to, double time, QuotedExtinction quoted) const;
    // K at `point` (as quotedDepthBetween counts it), at `time`.
    double quotedExtinctionAt(const dvec3& point, double time, QuotedExtinction quoted) const;
    // The share of the line from `from` to `to` where the smoke has data or claims none (1 but where a
    // simulation's domain lacks data, DataCoverage), at `time`.
    double dataCoverageBetween(const dvec3& from, const dvec3& to, double time) const;

    // The cache's side of the record passes: what a missed record is worth, and the records of a request.
    int missesToPay(const RecordRequest& request) const { return cache_.missesToPay(request); }
    std::vector<SurfaceRecord> makeRecords(const RecordRequest& request, const OpenRecord<SurfaceRecord>* open,
                                           Scratch& scratch, CacheVisit& visit) const {
        return cache_.makeRecords(request, open, scratch, visit);
    }
    std::vector<VolumeRecord> makeVolumeRecords(const RecordRequest& request, const OpenRecord<VolumeRecord>* open,
                                                Scratch& scratch, CacheVisit& visit) const {
        return cache_.makeVolumeRecords(request, open, scratch, visit);
    }
    // The windows of time records serve (-at, and the instants with data).
    const RecordWindows& recordWindows() const { return cache_.windows(); }

    // The seed of the samples of work item `index` (fixed by -u-, else new each run); pictures seed their
    // pixel jitter from it too.
    uint64_t seedFor(uint64_t index) const { return seeds_.of(index); }
    const Seeds& seeds() const { return seeds_; }
    const RenderScene& scene() const { return scene_; }
    const RenderSettings& settings() const { return settings_; }
    const SurfaceCache* cache() const { return cache_.cache(); }

    Spectrum radiance(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare,
                      RayRecord* record = nullptr) const override;
    Spectrum surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>& hit, const PathState& state,
                             PathContext& ctx, Spectrum* sourceShare) const override;
    Spectrum sampledRadiance(const dvec3& from, const SurfaceId& surface, const dvec3& dir, double pdf,
                             const PathState& parent, PathState& child, PathContext& ctx) const override;

private:
    PathContext contextFor(const RayQuery& q, WorkItem& item, RayOutputs& outputs) const;
    double primaryTmin(const dvec3& org) const;
    Spectrum radianceAlong(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum blendedHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const PathState& state,
                        PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum shadeHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, int mat, const PathState& state,
                      PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum scatterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Material& m,
                        const PathState& state, PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum emitterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Emitter& e,
                        const PathState& state, PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum metSource(const Spectrum& le, float share, int modifier, const Ray& ray, const SurfaceHit* hit,
                       const PathState& state, PathContext& ctx) const;
    Spectrum escaped(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum passThrough(const Ray& ray, const SurfaceHit& hit, const PathState& state, PathContext& ctx,
                         Spectrum* sourceShare) const;
    bool foundByChance(const Light& light, const PathState& state, const dvec3& from) const;
    Spectrum sampledSourceShare(const Spectrum& le, int light, const PathState& state, const Ray& ray,
                                const SurfaceHit* hit, PathContext& ctx, Spectrum* sourceShare) const;
    Spectrum sensorIrradiance(const dvec3& point, const dvec3& n, const SurfaceId& surface, double distance,
                              PathContext& ctx, RayRecord& rec, const dvec3& dir) const;

    const RenderScene& scene_;
    RenderSettings settings_;  // -av lifted to the sampling's bands
    Seeds seeds_;
    double epsilon_;  // offset for sensor points off their surface, relative to the scene size
    RussianRoulette roulette_;
    Instants instants_;
    Media media_;
    HitShading shading_;
    ShadowRays shadowRays_;
    LightSampler lights_;
    SkyPortals portals_;
    SunPatches patches_;
    CacheClient cache_;
    SurfaceScattering surfaces_;
    MediaTransport mediaTransport_;
};

}  // namespace brume
