// The media light crosses: Radiance's global medium (-me, -ma, -mg, in the sampling's bands), the mists a
// path is inside, and the smoke at each instant in use. Smoke at an instant is built once (its majorant
// grids bound the density then): a run prepares the instants it traces at before tracing there.
#pragma once
#include <map>
#include <optional>

#include "integrator/path_state.h"
#include "medium/instant_keys.h"
#include "medium/participating_media.h"
#include "world/render_scene.h"

namespace brume {

struct RenderSettings;

class Media {
public:
    // `settings` in the sampling's bands (inBands).
    Media(const RenderScene& scene, const RenderSettings& settings);

    // Builds the smoke at instant `time` (once; where nothing changes in time, once for every instant).
    // Not while rays are traced.
    void prepare(double time);
    // Forgets the smoke of every instant but `time`.
    void keepOnly(double time);
    // The smoke at a prepared instant (std::logic_error for another).
    const ParticipatingMedia& smokeAt(double time) const;

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
    int majorantCell_;
    InstantKeys instants_;  // one ParticipatingMedia per instant where the smoke changes in time, else one for all
    HomogeneousMedium global_;
    bool present_;
    std::map<double, ParticipatingMedia> smoke_;  // by InstantKeys::of
};

}  // namespace brume
