// A ray in double precision, as traced against the scene.
#pragma once
#include <glm/vec3.hpp>
#include <limits>

namespace brume {

using glm::dvec3;

struct Ray {
    dvec3 org;
    dvec3 dir;  // unit length
    double tmax = std::numeric_limits<double>::infinity();
    // Hits nearer than this are ignored: rays given by users may start exactly on a surface.
    double tmin = 0;
    // The surface the ray leaves (index in SceneGeometry::surfaces()), or -1. A ray never hits the planar surface it
    // starts on, and skips the root at its origin on a curved one: this, not an offset, is what keeps rays
    // from hitting their own surface at any scene scale.
    int leaving = -1;

    Ray() = default;
    Ray(const dvec3& o, const dvec3& d, double tMax = std::numeric_limits<double>::infinity(), int leavingSurface = -1)
        : org(o), dir(d), tmax(tMax), leaving(leavingSurface) {}

    dvec3 at(double t) const { return org + t * dir; }
};

}  // namespace brume
