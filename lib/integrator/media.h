// The media light crosses: Radiance's global medium (-me, -ma, -mg, in the sampling's bands), the mists a
// path is inside, and the smoke at each instant (the run's Instants build it).
#pragma once
#include "integrator/instants.h"
#include "integrator/path_state.h"
#include "medium/participating_media.h"
#include "world/render_scene.h"

namespace brume {

struct RenderSettings;

class Media {
public:
    // `settings` in the sampling's bands (inBands); `instants` outlives the media.
    Media(const RenderScene& scene, const RenderSettings& settings, Instants& instants);

    // The smoke at instant `time` (Instants::smokeAt).
    const ParticipatingMedia& smokeAt(double time) const { return instants_.smokeAt(time); }

    // Whether anything at all absorbs or scatters: else rays skip every question below.
    bool present() const { return present_; }
    // The global medium and the mists the ray is in. A ray leaving a mist it was not known to be in started
    // inside it (the eye or sensor in the mist): the mist fills the ray's way to that boundary, as Radiance
    // rules for mists with a source list.
    HomogeneousMedium homogeneousAlong(const Ray& ray, const SurfaceHit* hit, const PathState& state) const;
    // Whether some medium lies on a shadow ray's way to `distance` (smoke far from it costs a box test).
    bool attenuates(const Ray& ray, double distance, const PathState& state, const ParticipatingMedia& smoke) const;
    // Along a shadow ray that meets no surface before `distance`.
    Spectrum clearTransmittance(const Ray& ray, double distance, const PathState& state,
                                const ParticipatingMedia& smoke) const;

private:
    const RenderScene& scene_;
    Instants& instants_;
    HomogeneousMedium global_;
    bool present_;
};

}  // namespace brume
