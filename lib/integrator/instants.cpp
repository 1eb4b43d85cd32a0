#include "integrator/instants.h"

#include <algorithm>
#include <limits>

namespace brume {

Instants::Instants(const RenderScene& scene, int majorantCell)
    : scene_(scene),
      majorantCell_(majorantCell),
      timed_(scene.variesInTime()),
      last_(std::numeric_limits<double>::infinity()) {
    for (const SmokeDescription& s : scene.smoke()) {
        const std::vector<KeyFrame>& frames = s.frames->keyFrames();
        if (frames.size() > 1) last_ = std::min(last_, frames.back().time);
    }
}

const ParticipatingMedia& Instants::smokeAt(double time) {
    const double key = timed_ ? time : 0.0;
    std::lock_guard lock(mutex_);
    auto it = smoke_.find(key);
    if (it != smoke_.end()) return *it->second;
    std::vector<SmokeVolume> smoke;
    for (const SmokeDescription& d : scene_.smoke()) smoke.emplace_back(d, time, majorantCell_);
    return *smoke_.emplace(key, std::make_unique<const ParticipatingMedia>(std::move(smoke))).first->second;
}

void Instants::forgetBefore(double time) {
    if (timed_) smoke_.erase(smoke_.begin(), smoke_.lower_bound(time));
}

}  // namespace brume
