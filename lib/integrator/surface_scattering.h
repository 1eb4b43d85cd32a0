// The light a surface scatters toward the viewer, lobe by lobe: specular lobes by their rays, the sources'
// light by next-event estimation, sampled glossy and general lobes by one drawn ray each (weighted against
// next-event estimation), and diffuse interreflection from the irradiance cache or by paths.
#pragma once
#include "integrator/cache_client.h"
#include "integrator/deferred_bounces.h"
#include "integrator/light_sampler.h"
#include "integrator/sky_portals.h"
#include "integrator/sun_patches.h"
#include "integrator/tracer.h"

namespace brume {

class SurfaceScattering {
public:
    SurfaceScattering(const RenderScene& scene, const RenderSettings& settings, const LightSampler& lights,
                      const SkyPortals& portals, const SunPatches& patches, const CacheClient& cache,
                      const Tracer& tracer, const RussianRoulette& roulette)
        : scene_(scene), settings_(settings), lights_(lights), portals_(portals), patches_(patches), cache_(cache),
          tracer_(tracer), roulette_(roulette) {}

    // The radiance the lobes at the hit scatter along −sh.dir (leaving `surface`). Sources that rays of a
    // sampled path meet through straight transmissions go to `sourceShare` (see Tracer::radiance).
    Spectrum shade(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                   PathContext& ctx, Spectrum* sourceShare) const;

    // The state of a deferred bounce's continuation (as ambient() makes it for a first bounce's ray).
    PathState continuationOf(const DeferredBounce& bounce) const;

private:
    bool deferring(const PathState& state, bool beyond, const PathContext& ctx) const;
    Spectrum cosinePaths(const dvec3& point, const dvec3& normal, const SurfaceId& surface, int count,
                         const PathState& child, PathContext& ctx) const;
    Spectrum glossy(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                    PathContext& ctx) const;
    Spectrum general(const Shading& sh, const GeneralLobe& lobe, const SurfaceId& surface, const PathState& state,
                     PathContext& ctx) const;
    Spectrum ambient(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                     PathContext& ctx) const;

    const RenderScene& scene_;
    const RenderSettings& settings_;
    const LightSampler& lights_;
    const SkyPortals& portals_;
    const SunPatches& patches_;
    const CacheClient& cache_;
    const Tracer& tracer_;
    const RussianRoulette& roulette_;
};

}  // namespace brume
