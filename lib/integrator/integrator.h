// Radiance values along rays, as Radiance's rtrace defines them, computed without bias: next-event
// estimation of every source with multiple importance sampling, diffuse interreflection by path tracing
// (-ad paths at the first bounce, one after it, -ab bounces), specular and glossy rays, Russian roulette.
#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "cache/irradiance_cache.h"
#include "world/render_scene.h"
#include "integrator/settings.h"
#include "io/ray_record.h"
#include "medium/participating_media.h"
#include "pattern/pattern_evaluator.h"
#include "sampling/random.h"

namespace brume {

// The cache's record shape for a scene: -acache, -aa, and radius bounds from the scene's size and -ar.
RecordShape recordShape(const RenderScene& scene, const RenderSettings& settings);
// A new, empty irradiance cache if the settings call for one (-ab, -aa and -ad positive), else null.
std::shared_ptr<IrradianceCache> makeCache(const RenderScene& scene, const RenderSettings& settings);

class Integrator {
public:
    // `cache`: the irradiance cache to look records up in and add them to (shared with other integrators
    // of the same scene and settings, e.g. the frames of a sequence); by default a new one when -ab and -aa
    // are positive.
    Integrator(const RenderScene& scene, const RenderSettings& settings,
               std::shared_ptr<IrradianceCache> cache = nullptr);
    ~Integrator();

    // Runs work items 0 … count-1 (rays, pixels, sensors: each calls trace, irradiance or irradianceAtHit
    // and keeps the result) on all threads. With the irradiance cache (-ab > 0, -aa > 0), in passes: every
    // pass looks records up in a cache that does not change while it runs; an item that found no record
    // where it needed one runs again in the next pass, after the records asked for are made. Records are
    // made in an order fixed by the items' order, not by the threads, so results do not depend on -n.
    void forEach(size_t count, const std::function<void(size_t)>& item) const;
    // The irradiance cache, or null when -ab or -aa is 0.
    const std::shared_ptr<IrradianceCache>& cache() const { return cache_; }

    // Radiance arriving at org from direction dir (the ray's value). `index` seeds the ray's samples;
    // maxDistance > 0 limits how far the ray looks (rtrace -ld).
    // `tree`, if given, receives every ray traced for it.
    RayRecord trace(const dvec3& org, const dvec3& dir, uint64_t index, double maxDistance = 0,
                    RayTree* tree = nullptr) const;
    // Irradiance at point p on a surface facing n (rtrace -I).
    RayRecord irradiance(const dvec3& p, const dvec3& n, uint64_t index, RayTree* tree = nullptr) const;
    // Irradiance at the first opaque surface the ray meets; light sources give their radiance (rtrace -i).
    RayRecord irradianceAtHit(const dvec3& org, const dvec3& dir, uint64_t index, RayTree* tree = nullptr) const;

    // The seed of the samples of ray `index` (fixed by -u-, else new each run); pictures seed their pixel
    // jitter from it too.
    uint64_t seedFor(uint64_t index) const;
    const RenderScene& scene() const { return scene_; }

private:
    struct PathState;
    struct Context;
    struct CacheVisit;
    // The visit of the work item this thread runs in forEach (null outside it).
    static CacheVisit*& currentVisit();
    void makeRecords(const std::vector<RecordRequest>& requests) const;
    IrradianceRecord computeRecord(const RecordRequest& request, CacheVisit& visit) const;
    int recordDivisions(const RecordRequest& request) const;
    bool cachedAmbient(const Shading& sh, const dvec3& normal, const SurfaceId& surface, const Spectrum& coef,
                       const PathState& state, Context& ctx, Spectrum& irradiance) const;
    Spectrum radiance(const Ray& ray, const PathState& state, Context& ctx, RayRecord* record,
                      Spectrum* misEmission) const;
    Spectrum radianceAlong(const Ray& ray, const PathState& state, Context& ctx, RayRecord* record,
                           Spectrum* misEmission) const;
    Spectrum surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>& hit, const PathState& state,
                             Context& ctx, RayRecord* record, Spectrum* misEmission) const;
    // Media (media_transport.cpp).
    HomogeneousMedium homogeneousAlong(const Ray& ray, const SurfaceHit* hit, const PathState& state) const;
    Spectrum throughMedia(const Ray& ray, const std::optional<SurfaceHit>& hit, const HomogeneousMedium& h,
                          const PathState& state, Context& ctx, RayRecord* record, Spectrum* misEmission) const;
    Spectrum mediaTransmittance(const Ray& ray, double start, double end, const HomogeneousMedium& h,
                                Context& ctx) const;
    bool attenuates(const Ray& ray, double distance, const PathState& state) const;
    Spectrum clearTransmittance(const Ray& ray, double distance, const PathState& state, Context& ctx) const;
    Spectrum inScattered(const Ray& ray, double start, double end, const HomogeneousMedium& h,
                         const PathState& state, Context& ctx) const;
    Spectrum scattered(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, const PathState& state,
                       Context& ctx) const;
    int inScatteringSamples(double length) const;
    Spectrum blendedHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const PathState& state, Context& ctx,
                        RayRecord* record, Spectrum* misEmission) const;
    Spectrum shadeHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, int mat, const PathState& state,
                      Context& ctx, RayRecord* record, Spectrum* misEmission) const;
    Spectrum scatterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Material& m,
                        const PathState& state, Context& ctx, RayRecord* record, Spectrum* misEmission) const;
    Spectrum escaped(const Ray& ray, const PathState& state, RayRecord* record, Spectrum* misEmission) const;
    Spectrum emitterHit(const Ray& ray, const struct SurfaceHit& hit, const struct Shading& sh, const Emitter& e,
                        const PathState& state, Context& ctx, RayRecord* record, Spectrum* misEmission) const;
    Spectrum passThrough(const Ray& ray, const SurfaceHit& hit, const PathState& state, Context& ctx,
                         RayRecord* record, Spectrum* misEmission) const;
    Spectrum sensorIrradiance(const dvec3& point, const dvec3& n, const SurfaceId& surface, double distance,
                              Context& ctx, RayRecord& rec, const dvec3& dir) const;
    Spectrum shade(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                   Context& ctx, RayRecord* record, Spectrum* misEmission = nullptr) const;
    Spectrum sampledSourceShare(const Spectrum& le, int light, const PathState& state, const Ray& ray,
                                const SurfaceHit* hit, Spectrum* misEmission) const;
    Spectrum direct(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                    Context& ctx) const;
    bool samplesSource(const Light& light, const SurfaceId& surface) const;
    std::optional<Spectrum> oneSourceOf(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                        const PathState& state, Context& ctx) const;
    Spectrum directFrom(const Light& light, double closedForm, double share, const Shading& sh, const Lobes& lobes,
                        const SurfaceId& surface, const PathState& state, Context& ctx) const;
    int thresholdedCount(int count, double share) const;
    Spectrum ambient(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                     Context& ctx) const;
    Spectrum glossy(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                    Context& ctx) const;
    Spectrum general(const Shading& sh, const GeneralLobe& lobe, const SurfaceId& surface, const PathState& state,
                     Context& ctx) const;
    Spectrum sampledRadiance(const Shading& sh, const SurfaceId& surface, const dvec3& dir, double pdf,
                             const PathState& state, PathState& child, Context& ctx) const;
    Spectrum directViaMirrors(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                              Context& ctx) const;
    Spectrum response(const Shading& sh, const Lobes& lobes, const dvec3& l, double lightDensity,
                      bool withDiffuse = true) const;
    const Spectrum& sourceRadiance(const Light& light, const LightSample& s, const dvec3& from, Spectrum& scratch) const;
    Spectrum sourcePattern(const Light& light, const dvec3& point, const dvec3& normal, const dvec3& dir,
                           double distance) const;
    int shaderAt(const Ray& ray, const SurfaceHit& hit, Shading& sh, Context& ctx) const;
    const Material* alternateMaterial(const Ray& ray, const SurfaceHit& hit, const Emitter& illum, Shading& sh,
                                      Context& ctx) const;
    PatternEvaluator& patternEvaluator() const;
    PatternHit patternHit(const Ray& ray, const SurfaceHit& hit) const;
    void recordShadowRay(Context& ctx, const dvec3& from, const LightSample& s, const Light& light,
                         const Spectrum& value) const;
    bool mirrorImagesOn() const { return settings_.directRelays > 0 && !scene_.planarMirrors().empty(); }
    Spectrum shadowTransmittance(const Ray& ray, const Light& light, PathState state, Context& ctx) const;
    Spectrum transmittance(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind,
                           PathState& state, Context& ctx, SurfaceHit* reached) const;
    bool clipped(int modifier, const PathState& state) const;
    bool crossesAntimatter(int material, bool backside, PathState& state) const;
    bool crossesMist(int material, bool backside, PathState& state) const;
    PathState startingAt(const dvec3& point) const;
    bool spawn(const PathState& parent, PathState& child, const Spectrum& coef, bool reflection, Context& ctx,
               float& boost, bool roulette = false) const;
    bool bounceTail() const;
    double misWeightForLight(const Light& light, const PathState& state, const Ray& ray, const SurfaceHit* hit) const;
    double subdivision(const PathState& state) const;
    bool exactDirect(const PathState& state) const;
    double primaryTmin(const dvec3& org) const;

    const RenderScene& scene_;
    RenderSettings settings_;
    std::shared_ptr<IrradianceCache> cache_;
    mutable uint64_t passes_ = 0;  // forEach calls so far: they seed the records their items ask for
    uint64_t runSeed_;
    uint64_t id_;     // tells this integrator's per-thread pattern state from earlier integrators'
    double epsilon_;  // offset for sensor points off their surface, relative to the scene size
    HomogeneousMedium global_;  // -me, -ma, -mg in the sampling's bands
    ParticipatingMedia media_;  // the smoke at the settings' instant
    bool hasMedia_;             // anything at all absorbs or scatters
};

}  // namespace brume
