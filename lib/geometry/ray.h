// A ray in double precision, as traced against the scene.
#pragma once
#include <glm/vec3.hpp>
#include <limits>

namespace brume {

using glm::dvec3;

// Which surface a ray meets or leaves. Instances make copies of one prototype surface, and a mesh holds many
// triangles: each copy and each triangle is told apart.
struct SurfaceId {
    int surface = -1;   // index in SceneGeometry::surfaces(); -1 for a mesh triangle
    int instance = -1;  // the copy's placement (SceneGeometry::placements()); -1 for the scene's own surfaces
    int triangle = -1;  // a mesh triangle's index in its mesh, else -1
    bool operator==(const SurfaceId&) const = default;
    explicit operator bool() const { return surface >= 0 || triangle >= 0; }
};

struct Ray {
    dvec3 org;
    dvec3 dir;  // unit length
    double tmax = std::numeric_limits<double>::infinity();
    // Hits nearer than this are ignored: rays given by users may start exactly on a surface.
    double tmin = 0;
    // The surface the ray leaves, or none. A ray never hits the planar surface (or mesh triangle) it starts on,
    // and skips the root at its origin on a curved one: this, not an offset, is what keeps rays from hitting
    // their own surface at any scene scale.
    SurfaceId leaving;

    Ray() = default;
    Ray(const dvec3& o, const dvec3& d, double tMax = std::numeric_limits<double>::infinity(),
        SurfaceId leavingSurface = {})
        : org(o), dir(d), tmax(tMax), leaving(leavingSurface) {}

    dvec3 at(double t) const { return org + t * dir; }
};

}  // namespace brume
