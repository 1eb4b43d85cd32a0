// The sky and the ground seen through windows. Radiance's skies are glows at infinity that only its diffuse
// (ambient) rays find: deep in a room few of them pass through a window, and each that does carries the
// whole sky. Wherever the diffuse interreflection is path traced, as many samples aim at the scene's
// portals (its clear glazing toward the sky, RenderScene::portals) as rays go out at random, and the two are
// combined by multiple importance (the power heuristic): each direction counts once, the estimate stays
// unbiased, and it is still the light Radiance's ambient rays gather — nothing at -ab 0. -aP- turns it off.
#pragma once
#include <algorithm>

#include "cache/hemisphere_samples.h"
#include "integrator/hit_shading.h"
#include "integrator/path_context.h"
#include "integrator/shadow_rays.h"

namespace brume {

// How many samples aim at the sky (and at the sun's patches) where `rays` cosine-distributed rays go out: a
// quarter as many, one at least. Aimed samples are the costlier (a shadow ray through the glazing, the sky's
// pattern; a patch's shading and its own shadow ray) and the less noisy; the multiple-importance weights
// take the ratio (aimedPerRay).
inline int aimedCount(int rays) { return std::max(1, rays / 4); }

// The state of `rays` cosine-distributed rays from p (facing n) where samples aim too (`aiming`): what they
// meet then takes its share by the weights (SkyPortals::rayShare, SunPatches::rayShare).
inline void aimingFrom(PathState& state, const dvec3& p, const dvec3& n, int rays, bool aiming) {
    state.from = p;
    state.skyNormal = aiming ? n : dvec3(0);
    state.aimedPerRay = double(aimedCount(rays)) / rays;
}

class SkyPortals {
public:
    SkyPortals(const RenderScene& scene, const HitShading& shading, const ShadowRays& shadowRays, bool enabled);

    // Portals, and a sky or ground to see through them.
    bool active() const { return active_; }
    // Added to the radiance of `rays` cosine-distributed rays from p (facing n, leaving `surface`):
    // aimedCount(rays) samples aimed at the portals, each the sky's radiance it meets × the transmission of
    // the glazing it crosses × its multiple-importance weight × cosθ/(π·pdf), scaled to `rays` samples.
    // `state`: the rays' (the volumes they are in, their throughput). `aimed`, if given, receives each sample
    // that brings light, with its share of the irradiance.
    Spectrum sample(const dvec3& p, const dvec3& n, const SurfaceId& surface, int rays, const PathState& state,
                    PathContext& ctx, std::vector<AimedSample>* aimed = nullptr) const;
    // The share of the sky a ray keeps where it escapes along dir: all of it, unless it is a cosine-distributed
    // ray from a point that also aimed (aimingFrom).
    double rayShare(const PathState& ray, const dvec3& dir, Scratch& scratch) const;
    // The density (per steradian) with which sample() aims from p, facing n, along unit dir.
    double density(const dvec3& p, const dvec3& n, const dvec3& dir, Scratch& scratch) const;
    // The direction sample() aims along from p, facing n, for (u, v) in the unit square; nullopt where p sees
    // no portal to aim at.
    std::optional<dvec3> aim(const dvec3& p, const dvec3& n, double u, double v, Scratch& scratch) const;

private:
    // How p (facing n) sees each portal, into `choices`; false when it sees none it could aim at.
    bool choose(const dvec3& p, const dvec3& n, std::vector<PortalChoice>& choices) const;
    double densityOf(const dvec3& p, const dvec3& dir, const std::vector<PortalChoice>& choices) const;
    static dvec3 aimAt(const std::vector<PortalChoice>& choices, double u, double v, double& distance);
    // The radiance of the glow at infinity a ray escaping along dir meets, and which light it is (-1: none);
    // black where a source next-event estimation samples (the sun) comes first, as Radiance orders them.
    Spectrum skyToward(const dvec3& p, const dvec3& dir, PatternEvaluator& patterns, int& glow) const;

    const RenderScene& scene_;
    const HitShading& shading_;
    const ShadowRays& shadowRays_;
    bool active_;
};

}  // namespace brume
