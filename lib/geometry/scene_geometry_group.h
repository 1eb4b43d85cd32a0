// SceneGeometry's Embree scenes, shared by its building (scene_geometry.cpp) and its tracing
// (scene_intersect.cpp).
#pragma once
#include <glm/common.hpp>
#include <glm/gtx/component_wise.hpp>
#include <limits>

#include "geometry/scene_geometry.h"

namespace brume::scene_geometry_detail {

// Embree geometry IDs: in every group's scene, its triangles and its exact shapes; in the world's, the
// placements after them (placement p is ID kFirstPlacementGeom + p).
constexpr unsigned kTrianglesGeom = 0, kExactGeom = 1, kFirstPlacementGeom = 2;

// The placement of an Embree instance ID (-1: none, the scene's own surfaces).
inline int placementOf(unsigned instID) {
    return instID == RTC_INVALID_GEOMETRY_ID ? -1 : int(instID - kFirstPlacementGeom);
}

// The axis-aligned box of a shape.
void shapeBounds(const Shape& shape, dvec3& lo, dvec3& hi);

}  // namespace brume::scene_geometry_detail

namespace brume {

// One Embree scene: the scene's own surfaces, or one prototype's.
struct SceneGeometry::Group {
    const SceneGeometry* owner = nullptr;
    RTCScene scene = nullptr;
    int firstSurface = 0, endSurface = 0;
    const Mesh* mesh = nullptr;        // a mesh prototype: triangle primIDs are the mesh's triangles
    std::vector<int> triangleSurface;  // polygon triangle primID → surface
    std::vector<int> exactSurface;     // user-geometry primID → surface
    dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};

    SurfaceId idOf(unsigned geomID, unsigned primID, int placement) const {
        if (geomID == scene_geometry_detail::kExactGeom) return {exactSurface[primID], placement, -1};
        if (mesh) return {-1, placement, int(primID)};
        return {triangleSurface[primID], placement, -1};
    }
};

}  // namespace brume
