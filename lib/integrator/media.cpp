#include "integrator/media.h"

#include <stdexcept>

#include "integrator/settings.h"

namespace brume {

Media::Media(const RenderScene& scene, const RenderSettings& settings)
    : scene_(scene), majorantCell_(settings.majorantCell), instants_(scene.variesInTime()), global_(settings.medium) {
    present_ = !global_.clear() || scene.hasMists() || !scene.smoke().empty();
}

void Media::prepare(double time) {
    double key = instants_.of(time);
    if (smoke_.count(key)) return;
    std::vector<SmokeVolume> smoke;
    for (const SmokeDescription& d : scene_.smoke()) smoke.emplace_back(d, time, majorantCell_);
    smoke_.emplace(key, ParticipatingMedia(std::move(smoke)));
}

void Media::keepOnly(double time) {
    std::erase_if(smoke_, [&](const auto& entry) { return !instants_.keptAt(entry.first, time); });
}

const ParticipatingMedia& Media::smokeAt(double time) const {
    auto it = smoke_.find(instants_.of(time));
    if (it == smoke_.end()) throw std::logic_error("the smoke at an instant not prepared");
    return it->second;
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
