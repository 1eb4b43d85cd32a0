// The irradiance caches as light transport uses them: lookups at diffuse shading points and at scattering
// points in media (noting the records they miss), and the rays a record is made of (a hemisphere's, a
// sphere's).
#pragma once
#include "cache/record_windows.h"
#include "cache/sphere_samples.h"
#include "cache/surface_cache.h"
#include "cache/volume_cache.h"
#include "integrator/hit_shading.h"
#include "integrator/light_sampler.h"
#include "integrator/media.h"
#include "integrator/settings.h"
#include "integrator/sky_portals.h"
#include "integrator/sun_patches.h"
#include "integrator/tracer.h"

namespace brume {

class CacheClient {
public:
    // `cache` and `volumes` may be null (no cache: -ab or -aa 0); `seeds` seed the records' rays by their
    // requests' keys; `windows`: the windows of time records serve.
    CacheClient(const SurfaceCache* cache, const VolumeCache* volumes, const RenderScene& scene,
                const RenderSettings& settings, const Tracer& tracer, const HitShading& shading, const Media& media,
                const LightSampler& lights, const SkyPortals& portals, const SunPatches& patches, Seeds seeds,
                RecordWindows windows)
        : cache_(cache), volumes_(volumes), scene_(scene), settings_(settings), tracer_(tracer), shading_(shading),
          media_(media), lights_(lights), portals_(portals), patches_(patches), seeds_(seeds), windows_(windows) {}

    // The windows of time records serve.
    const RecordWindows& windows() const { return windows_; }

    const SurfaceCache* cache() const { return cache_; }
    const VolumeCache* volumes() const { return volumes_; }
    // The indirect irradiance at a diffuse shading point from the records (true). Where there is none, the
    // work item's visit asks for one (missed by a ray of the path's weight times the lobe's coefficient
    // `coef`) and the path samples the light itself (false) — unless the item waits for the record: then
    // true with 0, the item running again.
    bool irradiance(const Receiver& at, const SurfaceId& surface, double pathWeight, const Spectrum& coef,
                    PathContext& ctx, Spectrum& value) const;

    // The light a medium's `phase` at `at.point` scatters back along a ray of direction `dir`, from the volume
    // records (true): all of it but what LightSampler::besidesRecords gives, or with `sources` false all but
    // the sources' (next-event estimation's) light; where there is none, as irradiance() (the path's weight
    // times the phase's coefficient weighs the miss).
    bool inScattered(const Receiver& at, const dvec3& dir, const PhaseMixture& phase, bool sources,
                     double pathWeight, PathContext& ctx, Spectrum& value) const;

    // Radiance's -ad at the first bounce, scaled down by the looking ray's weight deeper in a path (at least
    // kMinDivisions).
    int recordDivisions(const RecordRequest& request) const {
        int ad = settings_.ambientDivisions;
        if (request.at.level == 0) return ad;
        return std::min(ad, std::max(kMinDivisions, int(ad * request.weight)));
    }
    // How many lookups must miss a record before it is worth making: one at the first bounce (a primary ray's
    // value waits for it); deeper, as many as its samples, so that a record costs no more than the paths it
    // spares.
    int missesToPay(const RecordRequest& request) const {
        return request.at.level == 0 ? 1 : std::max(1, recordDivisions(request));
    }
    // The records a request calls for (RecordWindows): the record of its instant, or, from `open` (else null),
    // those of a window, traced with the open record's samples (its request's), each by recordAt.
    std::vector<SurfaceRecord> makeRecords(const RecordRequest& request, const OpenRecord<SurfaceRecord>* open,
                                           Scratch& scratch, CacheVisit& visit) const;
    std::vector<VolumeRecord> makeVolumeRecords(const RecordRequest& request, const OpenRecord<VolumeRecord>* open,
                                                Scratch& scratch, CacheVisit& visit) const;

private:
    // A record: the radiance of stratified rays over the hemisphere (more passes of them where their standard
    // error asks, see passesFor), each continuing one bounce deeper (where
    // the cache, or paths, give the light of further bounces), and as many samples aimed at the sky through
    // the windows and at the sun's patches (SkyPortals, SunPatches), which count in the record's gradients
    // and zone as equivalent point sources. Sources these rays meet are left out: records hold indirect
    // light, next-event estimation gives the direct. Their own misses go to `visit`. At the request's instant.
    SurfaceRecord recordAt(const RecordRequest& request, Scratch& scratch, CacheVisit& visit) const;
    // A volume record: the radiance of rays stratified over the sphere, each continuing one bounce deeper, the
    // sources they meet left out as a surface record's rays leave them, and each source's light by
    // sourceSamples of next-event estimation's shadow rays (LightSampler::arriving). The sphere's rays come in
    // passes of a quarter of -ad, as many as their standard error asks (volumePassesFor).
    VolumeRecord volumeRecordAt(const RecordRequest& request, Scratch& scratch, CacheVisit& visit) const;

    static constexpr int kMinDivisions = 16;
    // A volume record's shadow rays per source: an eighth of its sphere's rays, at least 8 (128 at -ad 1024,
    // where a view ray's in-scattering point takes one to four; a record's light is shared by the many
    // points in its zone).
    int sourceSamples(const RecordRequest& request) const { return std::max(8, recordDivisions(request) / 8); }
    // A first-bounce volume record's first pass over the sphere: a quarter of its divisions (its passes make
    // up the rest where they must); deeper records make one pass of all theirs.
    int firstPassDivisions(const RecordRequest& request) const {
        int divisions = recordDivisions(request);
        return request.at.level == 0 ? std::max(kMinDivisions, divisions / kVolumePasses) : divisions;
    }
    static constexpr int kVolumePasses = 4;
    // The standard error a first-bounce volume record's sphere aims for, relative to all its light (the
    // sources' included: where a lamp gives most of a point's light, the rest's noise matters little), as a
    // share of -aa. Looser than a surface record's: the rays that look volume records up (view rays, record
    // rays through a medium) gather many along their way, which averages their noise.
    static constexpr double kVolumeNoiseShare = 0.3;
    // The standard error a record's samples aim for, relative to all the light its surface gets (see
    // passesFor), as a share of -aa: a record's noise is not an error its zone's neighbours average out, as
    // every lookup in the zone shares it. 1.5 % at -aa .1: at -ad 1024 daylit rooms' records (1-1.4 % of
    // their indirect light) take one or two passes, while those seeing through a white fog (about 3 %) take
    // up to four, and those of a wall behind a lamp's halo in fog (about 5 %) up to eight.
    static constexpr double kNoiseShare = 0.15;

    // How many passes over its strata a first-bounce surface record's rays make (samplePasses), from its
    // `first` pass and the `known` brightness of the rest of the light there (samples aimed besides them, and
    // the sources' light straight: a record's noise shows on its surface in proportion to all the light the
    // surface gets, and a wall a lamp lights takes fewer passes than a ceiling it does not; in the smoky
    // corridor of bench/volume_cache.py's pictures, albedo .8, 3.4 passes in place of 6.9). Deeper records
    // take one: their noise reaches an answer averaged over the many records a first-bounce record's rays meet.
    int passesFor(const HemisphereSamples& first, double known) const;
    // The irradiance straight from the sources at a surface record's point, from a few shadow rays (-ad / 16
    // over all sources, at least 2 a source): enough to weigh its share of the light, for passesFor.
    double directIrradiance(const RecordRequest& request, const PathState& child, PathContext& ctx) const;
    // The same for a volume record's sphere: 1 to kVolumePasses, from its first pass and the brightness
    // `known` of the sources' light (as a mean radiance over the sphere).
    int volumePassesFor(const SphereSamples& first, double known, int level) const;
    // One ray per stratum of `samples`' pass `pass`, leaving `leaving`.
    template <class Samples>
    void tracePass(Samples& samples, int pass, const SurfaceId& leaving, const PathState& child,
                   PathContext& ctx) const;

    // The context and the first state of a record's rays, one bounce deeper than the request.
    PathContext recordContext(const RecordRequest& q, Scratch& scratch, CacheVisit& visit, RayOutputs& outputs) const;
    PathState recordRays(const RecordRequest& q, Scratch& scratch) const;
    // After a lookup found no record: notes the request (missed by a ray of the path's weight times the
    // coefficient `coef`); true with value 0 when the item waits for it, false when the path samples on.
    bool waitsFor(const Receiver& at, const SurfaceId& surface, double pathWeight, const Spectrum& coef,
                  PathContext& ctx, Spectrum& value) const;
    // The largest extinction coefficient of the media at p (of the mists a path of `state` is in, the global
    // medium's and the smoke's).
    double extinctionAt(const dvec3& p, const PathState& state, const PathContext& ctx) const;
    // The distance from p to the nearest lamp's surface (not less than its radius); infinite without lamps.
    double nearestSource(const dvec3& p) const;
    // Record r's zone radius kept where its edge needs it: at most ε over the largest extinction at its point
    // (`extinction`, the builder's) and at the six points of its edge along the axes. The builder's ε / σ_t
    // looks at the record's point only: a zone made on the thin side of a change reached into the denser
    // smoke as far as on its other side, and lookups there read the thinner side's light. In
    // bench/furnace.py's blob at g 0 (one-record lookups, the blob's density falling outward), the wall's
    // irradiance was 1 % low.
    double heldRadius(const VolumeRecord& r, double extinction, const PathState& state, const PathContext& ctx) const;

    const SurfaceCache* cache_;
    const VolumeCache* volumes_;
    const RenderScene& scene_;
    const RenderSettings& settings_;
    const Tracer& tracer_;
    const HitShading& shading_;
    const Media& media_;
    const LightSampler& lights_;
    const SkyPortals& portals_;
    const SunPatches& patches_;
    Seeds seeds_;
    RecordWindows windows_;
};

}  // namespace brume
