// SceneGeometry's Embree scenes, shared by its building (scene_geometry.cpp) and its tracing
// (scene_intersect.cpp).
#pragma once
#include <glm/common.hpp>
#include <glm/gtx/component_wise.hpp>
#include <limits>

#include "geometry/local_frame.h"
#include "world/scene_geometry.h"

namespace brume::scene_geometry_detail {

// Embree geometry IDs: in every group's scene, its float triangles and its exact shapes; in the world's, the
// placements after them (placement p is ID kFirstPlacementGeom + p).
constexpr unsigned kTrianglesGeom = 0, kExactGeom = 1, kFirstPlacementGeom = 2;

// The placement of an Embree instance ID (-1: none, the scene's own surfaces).
inline int placementOf(unsigned instID) {
    return instID == RTC_INVALID_GEOMETRY_ID ? -1 : int(instID - kFirstPlacementGeom);
}

// The axis-aligned box of a shape, and of a mesh's triangle t.
Bounds3 shapeBounds(const Shape& shape);
Bounds3 triangleBounds(const Mesh& mesh, size_t t);

// One primitive of a group: a surface and, for a polygon, the triangle of its triangulation (-1 for curved
// shapes and rings); or (surface -1) a mesh's triangle.
struct Piece {
    int surface;
    int triangle;
};

}  // namespace brume::scene_geometry_detail

namespace brume {

// One Embree scene: the scene's own surfaces, or one prototype's. Embree holds its coordinates as float
// offsets from frame.origin.
struct SceneGeometry::Group {
    const SceneGeometry* owner = nullptr;
    RTCScene scene = nullptr;
    int firstSurface = 0, endSurface = 0;
    const Mesh* mesh = nullptr;  // a mesh prototype: triangle primIDs are the mesh's triangles
    LocalFrame frame;
    // The largest |offset from the origin| of its float triangles: their rounding is kFloatError of it.
    double floatReach = 0;
    // Float triangle primID → polygon and its triangle, or mesh triangle (empty: a mesh's own, all float).
    std::vector<scene_geometry_detail::Piece> triangles;
    std::vector<scene_geometry_detail::Piece> exact;      // user-geometry primID → exact shape or polygon triangle
    Bounds3 box;                                          // of all its surfaces, in its own coordinates

    SurfaceId idOf(unsigned geomID, unsigned primID, int placement) const {
        bool isExact = geomID == scene_geometry_detail::kExactGeom;
        const scene_geometry_detail::Piece* piece = isExact ? &exact[primID] : triangles.empty() ? nullptr : &triangles[primID];
        if (!piece) return {-1, placement, int(primID)};  // a mesh whose triangles all are float ones
        if (piece->surface < 0) return {-1, placement, piece->triangle};
        return {piece->surface, placement, -1};
    }
};

}  // namespace brume
