// What reaches a source along a shadow ray: through clear glass and trans (their transmission), antimatter,
// mists and media (their transmittance); stopped by opaque surfaces and other sources.
#pragma once
#include "integrator/hit_shading.h"
#include "integrator/media.h"
#include "integrator/path_context.h"

namespace brume {

class ShadowRays {
public:
    ShadowRays(const RenderScene& scene, const HitShading& shading, const Media& media)
        : scene_(scene), shading_(shading), media_(media) {}

    // Along the shadow ray toward `light`: 1 if nothing is in the way, the product of the transmissions it
    // crosses, 0 if something opaque or another source blocks it.
    Spectrum toSource(const Ray& ray, const Light& light, PathState state, PathContext& ctx) const {
        return toSurface(ray, light.surface(), light.isDistant(), light.emitter().kind, state, ctx, nullptr);
    }
    // Along a shadow ray to surface `target` (or, for a source at infinity, out of the scene): the
    // transmission of what it crosses, black if blocked; `state` follows the volumes it enters and leaves.
    // `reached` receives the hit on the target.
    Spectrum toSurface(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind, PathState& state,
                       PathContext& ctx, SurfaceHit* reached) const;
    // The light flames emit toward ray.org along it, up to ray.tmax or what stops shadow rays first: ∫ T σ_a B dt,
    // T the transmission of what lies between (ParticipatingMedia::emittedAlong at `points` points in each
    // stretch of media).
    Spectrum flameLightAlong(const Ray& ray, int points, PathState state, PathContext& ctx) const;

private:
    // The walk both take: surfaces crossed, passed or stopping it; `stretch(ray, end, h, t)` gives the media's
    // transmission over [0, end] of each stretch between surfaces (h the homogeneous medium there, t the
    // transmission before it).
    template <class Stretch>
    Spectrum walk(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind, PathState& state,
                  PathContext& ctx, SurfaceHit* reached, const Stretch& stretch) const;

    const RenderScene& scene_;
    const HitShading& shading_;
    const Media& media_;
};

}  // namespace brume
