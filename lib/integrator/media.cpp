#include "integrator/media.h"

#include "integrator/settings.h"

namespace brume {

Media::Media(const RenderScene& scene, const RenderSettings& settings, Instants& instants)
    : scene_(scene), instants_(instants), global_(settings.medium) {
    present_ = !global_.clear() || scene.hasMists() || !scene.smoke().empty();
}

HomogeneousMedium Media::homogeneousAlong(const Ray& ray, const SurfaceHit* hit, const PathState& state) const {
    HomogeneousMedium h = global_;
    for (int i = 0; i < state.mists.count; ++i) h = scene_.mist(state.mists.objects[i])->inside(h);
    if (!hit || !scene_.hasMists()) return h;
    int material = scene_.materialObject(hit->surface);
    const Mist* mist = material >= 0 ? scene_.mist(material) : nullptr;
    if (mist && glm::dot(hit->normal, ray.dir) > 0 && !state.mists.contains(material)) h = mist->inside(h);
    return h;
}

bool Media::attenuates(const Ray& ray, double distance, const PathState& state, const ParticipatingMedia& smoke) const {
    return present_ && (!homogeneousAlong(ray, nullptr, state).clear() || smoke.smokeAlong(ray, 0, distance));
}

Spectrum Media::clearTransmittance(const Ray& ray, double distance, const PathState& state,
                                   const ParticipatingMedia& smoke) const {
    return smoke.transmittance(ray, 0, distance, homogeneousAlong(ray, nullptr, state));
}

}  // namespace brume
