#include "geometry/local_frame.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtx/component_wise.hpp>

namespace brume {

namespace {

constexpr double kHugeRatio = 1e3, kNearRatio = 1e4;

// The lower median: a value of the list, so that moving every item moves it by exactly as much.
double lowerMedian(std::vector<double> v) {
    auto mid = v.begin() + (v.size() - 1) / 2;
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

}  // namespace

LocalFrame::LocalFrame(const std::vector<Bounds3>& items, double outerTypical) {
    std::vector<double> sizes, centres[3];
    for (const Bounds3& b : items) {
        if (b.empty()) continue;
        sizes.push_back(glm::length(b.hi - b.lo));
        for (int k = 0; k < 3; ++k) centres[k].push_back(0.5 * (b.lo[k] + b.hi[k]));
    }
    if (sizes.empty()) return;
    for (int k = 0; k < 3; ++k) origin_[k] = lowerMedian(centres[k]);
    typical_ = lowerMedian(sizes);
    // Items of no extent (a point-like polygon cannot be, but a ball of radius 0 can) set no scale.
    if (!(typical_ > 0)) typical_ = std::max(1e-300, *std::max_element(sizes.begin(), sizes.end()));
    hugeSize_ = kHugeRatio * std::min(typical_, outerTypical);
}

bool LocalFrame::huge(const Bounds3& b) const { return glm::length(b.hi - b.lo) > hugeSize_; }

bool LocalFrame::near(const Bounds3& b) const { return reachFrom(b, origin_) <= kNearRatio * typical_; }

bool LocalFrame::reaches(const Bounds3& b) const {
    dvec3 gap = glm::max(dvec3(0), glm::max(b.lo - origin_, origin_ - b.hi));
    return glm::compMax(gap) <= kNearRatio * typical_;
}

double reachFrom(const Bounds3& b, const dvec3& origin) {
    return glm::compMax(glm::max(glm::abs(b.lo - origin), glm::abs(b.hi - origin)));
}

}  // namespace brume
