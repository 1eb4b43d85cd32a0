// An axis-aligned box in world space; the default one is empty.
#pragma once
#include <algorithm>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
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
    // Whether p is in the box, its faces included.
    bool contains(const dvec3& p) const { return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi)); }
};

// Narrows [tmin, tmax] to where org + t·dir is inside the box (closed, so grazing lines count); false where
// nothing of it is.
inline bool clipToBox(const Bounds3& b, const dvec3& org, const dvec3& dir, double& tmin, double& tmax) {
    if (b.empty()) return false;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0) {
            if (org[a] < b.lo[a] || org[a] > b.hi[a]) return false;
            continue;
        }
        double t0 = (b.lo[a] - org[a]) / dir[a], t1 = (b.hi[a] - org[a]) / dir[a];
        tmin = std::max(tmin, std::min(t0, t1));
        tmax = std::min(tmax, std::max(t0, t1));
    }
    return tmin <= tmax;
}

}  // namespace brume
