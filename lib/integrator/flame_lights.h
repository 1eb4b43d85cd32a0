// Flames as light sources: next-event estimation of the light glowing smoke sends to a surface or a medium
// point (one routine for both, through a Scatterer), weighed by the power heuristic against the rays drawn
// from the point's lobes or phase function, which keep only their share of the flame light they meet
// (rayShare; Lambertian lobes leave all of it here, as they do every source's).
//
// A sample draws a direction toward where the flames glow (ParticipatingMedia::sampleFlameDirection): along
// that direction, through the flames' box, the light the smoke emits toward the point, ∫ T σ_a B dt up to
// whatever stops shadow rays, is estimated whole (ShadowRays::flameLightAlong), so that a thick flame's light
// comes from its near side and a thin one's from all along. The direction's density per steradian, in closed
// form (flameDirectionDensity), is what the lobes' rays are weighed against. Where the flames' smoke scatters,
// the light it scatters once within the flames' box along that direction is part of the sample too (at one
// point of the chord, uniform, with one flame sample of its own): a flame's own soot, lit by its core, glows
// around it, and rays drawn from lobes found that light only where they happened to cross the core (a tail
// of rare, huge values beside a flame one cannot see into). Rays drawn from lobes keep their share of it
// against these samples (`emissionShare` at their scattering points inside the box), as of the emission.
#pragma once
#include <optional>

#include "integrator/path_context.h"
#include "integrator/scatterer.h"
#include "integrator/shadow_rays.h"

namespace brume {

class FlameLights {
public:
    explicit FlameLights(const ShadowRays& shadowRays) : shadowRays_(shadowRays) {}

    // The flames' light scattered toward the viewer by `at` (leaving `surface`), by sampleCount samples for
    // the -ds ratio `subdivision` there, and what the flames' smoke scatters of it once within their box; the
    // emitted light times `shareWithin` (a drawn ray's share of it at a point inside the box: the samples of the
    // ray's origin count that light, scattered there once, too).
    // `scatteredOnce`: whether the smoke's scattering counts, a bounce (-ab) being left there.
    Spectrum sample(const Scatterer& at, const SurfaceId& surface, const PathState& state, double subdivision,
                    bool scatteredOnce, PathContext& ctx, double shareWithin = 1) const;
    // The share of the flame light met along `dir` that a ray drawn from a lobe keeps (`state` the ray's, as
    // LightSampler::drawnFrom made it): its power-heuristic weight against the samples drawn at its origin;
    // nullopt along directions no sample can take (the ray's light, whatever lobe drew it).
    std::optional<double> rayShare(const ParticipatingMedia& smoke, const PathState& state, const dvec3& dir) const;
    // How many samples a point gets: as a source, by the angular size of the flames' box from it.
    static int sampleCount(const ParticipatingMedia& smoke, const dvec3& point, double subdivision, double weight);

private:
    // n samples of `points` points each: the emitted light times `emittedShare`, and (with `scatteredOnce`) the
    // light scattered once within the box, whole.
    Spectrum estimate(const Scatterer& at, const SurfaceId& surface, const PathState& state, int n, int points,
                      bool scatteredOnce, double emittedShare, PathContext& ctx) const;
    // The light the flames' smoke scatters once toward `from` along `dir` over [t0, t1] (inside their box).
    Spectrum scatteredWithin(const dvec3& from, const dvec3& dir, double t0, double t1, const SurfaceId& surface,
                             const PathState& state, PathContext& ctx) const;

    const ShadowRays& shadowRays_;
};

}  // namespace brume
