// Next-event estimation: the light reaching a point straight from the sources, or through their images in
// flat mirrors, along shadow rays that cross clear glass, antimatter and media — one routine for surface
// and medium points (pbrt-v4's SampleLd), which weighs each source sample by the scatterer's response.
#pragma once
#include "cache/source_samples.h"
#include "integrator/flame_lights.h"
#include "integrator/hit_shading.h"
#include "integrator/media.h"
#include "integrator/path_context.h"
#include "integrator/scatterer.h"
#include "integrator/settings.h"
#include "integrator/shadow_rays.h"

namespace brume {

// The share a source's light keeps where next-event estimation finds it at the end of a drawn ray whose
// origin also aimed at that light by another route (SunPatches): 1 where nothing else counts it.
class SourceShares {
public:
    virtual ~SourceShares() = default;
    virtual double rayShare(const Light& light, const Scatterer& at, const SurfaceId& surface, const PathState& state,
                            PathContext& ctx) const = 0;
};

class LightSampler {
public:
    LightSampler(const RenderScene& scene, const RenderSettings& settings, const HitShading& shading,
                 const Media& media, const ShadowRays& shadowRays)
        : scene_(scene), settings_(settings), shading_(shading), media_(media), shadowRays_(shadowRays),
          flames_(shadowRays), sensorRays_(sensorRaysPerSource(scene)) {}

    // The sources' and the flames' light scattered toward the viewer by `at` (leaving `surface`, none in a
    // medium), each source's taking its share (`shares`, if given) where it is not found.
    Spectrum sampleLd(const Scatterer& at, const SurfaceId& surface, const PathState& state, PathContext& ctx,
                      const SourceShares* shares = nullptr) const;
    // The same at a point in a medium where the flames' emitted light takes `flameShare` of it (FlameLights).
    Spectrum sampleLdSharingFlames(const Scatterer& at, const PathState& state, PathContext& ctx, double flameShare) const;
    // What volume records leave to next-event estimation at a point in a medium: the flames' light and the
    // sources' seen in flat mirrors (they hold the rest, see arriving).
    Spectrum besidesRecords(const Scatterer& at, const PathState& state, PathContext& ctx) const;
    // `count` stratified samples of `light`'s light arriving straight at `at`, as much as gets through what lies
    // between (none that is blocked): at a point in a medium for a volume record, or on the side of surface
    // `leaving` that `at`'s normal faces (samples from behind it left out) for a surface record's estimate of
    // its direct light.
    void arriving(const Light& light, const Receiver& at, const SurfaceId& leaving, int count, const PathState& state,
                  PathContext& ctx, SourceSamples& out) const;
    // One source's light scattered toward the viewer by `at`.
    Spectrum fromSource(const Light& light, const Scatterer& at, const SurfaceId& surface, const PathState& state,
                        PathContext& ctx) const {
        return directFrom(light, -1, 1.0, 1.0, at, surface, state, ctx);
    }

    // A ray drawn from a lobe at `from` with density `pdf`, child of `parent`: it remembers how next-event
    // estimation counted sources there, so that a source it meets takes only its share (misWeight).
    void drawnFrom(PathState& child, const dvec3& from, double pdf, const PathState& parent) const;
    // The multiple-importance weight of a source met by a drawn ray (power heuristic against next-event
    // estimation's density × sample count at the ray's origin); `hit` on the source, null at infinity.
    double misWeight(const Light& light, const PathState& state, const Ray& ray, const SurfaceHit* hit) const;
    // Flames as sources: for the share of their light rays drawn from lobes keep.
    const FlameLights& flames() const { return flames_; }
    // Whether next-event estimation reaches sources through mirror images (-dr > 0 and some flat mirror).
    bool mirrorImagesOn() const { return settings_.directRelays > 0 && !scene_.planarMirrors().empty(); }

private:
    double subdivision(const PathState& state) const;
    bool bounceLeft(const PathState& state) const;
    Spectrum sourcesLd(const Scatterer& at, const SurfaceId& surface, const PathState& state, PathContext& ctx,
                       const SourceShares* shares) const;
    bool exactDirect(const PathState& state) const { return state.depth == 0; }
    static int sensorRaysPerSource(const RenderScene& scene);
    int thresholdedCount(int count, double share) const;
    bool samplesSource(const Light& light, const SurfaceId& surface) const;
    std::optional<Spectrum> oneSourceOf(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                                        PathContext& ctx, const SourceShares* shares) const;
    // How much of a source sample's light the way from `shadow`'s origin to it (`distance` along it) lets
    // through: Clear or Blocked where all or none, else Unsure with `t`, per channel.
    Occlusion passage(const Ray& shadow, const Light& light, double distance, const PathState& state,
                      PathContext& ctx, Spectrum& t) const;
    Spectrum keptFrom(const Light& light, double closedForm, double share, double weight, const Scatterer& at,
                      const SurfaceId& surface, const PathState& state, PathContext& ctx,
                      const SourceShares* shares) const;
    Spectrum directFrom(const Light& light, double closedForm, double share, double scale, const Scatterer& at,
                        const SurfaceId& surface, const PathState& state, PathContext& ctx) const;
    Spectrum directViaMirrors(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                              PathContext& ctx) const;
    const Spectrum& sourceRadiance(const Light& light, const LightSample& s, const dvec3& from, Spectrum& scratch,
                                   PatternEvaluator& patterns) const;
    void recordShadowRay(PathContext& ctx, const dvec3& from, const LightSample& s, const Light& light,
                         const Spectrum& value) const;

    const RenderScene& scene_;
    const RenderSettings& settings_;
    const HitShading& shading_;
    const Media& media_;
    const ShadowRays& shadowRays_;
    FlameLights flames_;
    int sensorRays_;  // the fewest shadow rays a sensor sends each source
};

}  // namespace brume
