// An axis-aligned box in world space; the default one is empty.
#pragma once
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace brume {

using glm::dvec3;

struct Bounds3 {
    dvec3 lo{std::numeric_limits<double>::infinity()};
    dvec3 hi{-std::numeric_limits<double>::infinity()};

    bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    void include(const dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    void include(const Bounds3& b) {
        if (!b.empty()) include(b.lo), include(b.hi);
    }
};

}  // namespace brume
