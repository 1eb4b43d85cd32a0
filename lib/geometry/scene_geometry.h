// The scene's surfaces in one Embree scene: polygons as triangles, spheres, cones and rings as exact user
// geometry. Embree finds the nearest candidate; the hit point and normal are then computed in double
// precision from the exact shape, so shading never sees float rounding.
#pragma once
#include <embree3/rtcore.h>

#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "geometry/surface.h"

namespace brume {

struct SurfaceHit {
    double t;
    dvec3 point;
    dvec3 normal;  // unit geometric normal, oriented as Radiance orients the surface (not toward the ray)
    int surface;   // index in SceneGeometry::surfaces()
};

class SceneGeometry {
public:
    explicit SceneGeometry(std::vector<Surface> surfaces);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    // The nearest surface along the ray before ray.tmax, never the root of ray.leaving at its origin.
    std::optional<SurfaceHit> intersect(const Ray& ray) const;

    const std::vector<Surface>& surfaces() const { return surfaces_; }
    // Bounding box of all surfaces (empty box, min > max, when there are none).
    dvec3 boundsMin() const { return lo_; }
    dvec3 boundsMax() const { return hi_; }

private:
    void addTriangles();
    void addExactShapes();
    static void exactBounds(const RTCBoundsFunctionArguments* args);
    static void exactIntersect(const RTCIntersectFunctionNArguments* args);

    std::vector<Surface> surfaces_;
    std::vector<int> triangleSurface_;  // Embree triangle primID -> surface
    std::vector<int> exactSurface_;     // Embree user-geometry primID -> surface
    unsigned triangleGeom_ = RTC_INVALID_GEOMETRY_ID, exactGeom_ = RTC_INVALID_GEOMETRY_ID;
    dvec3 lo_, hi_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

}  // namespace brume
