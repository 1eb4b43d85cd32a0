// The scene's surfaces in Embree: polygons and mesh triangles as float triangles, spheres, cones and rings (and
// polygons too large or too far for floats: local_frame.h) as exact user geometry; each prototype (an
// instanced octree's surfaces, a mesh) in an Embree scene of its own, built once and placed by Embree
// instances, its float coordinates offsets from a local origin. Embree's float BVH only proposes candidates:
// each is decided in double precision from the exact shape (in its prototype's coordinates for placed
// surfaces), and the nearest by exact distance wins, so neither hits nor shading see float rounding.
#pragma once
#include <embree3/rtcore.h>

#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/ray.h"
#include "world/scene_layout.h"
#include "geometry/surface.h"

namespace brume {

struct SurfaceHit {
    double t;
    dvec3 point;
    dvec3 normal;  // unit geometric normal, oriented as Radiance orients the surface (not toward the ray)
    SurfaceId surface;
    // Radiance's normal perturbation: the shading normal is normalize(normal + perturbation). Interpolated mesh
    // vertex normals give it; 0 elsewhere.
    dvec3 perturbation{0};
    // Radiance's local coordinates Lu, Lv: a mesh's interpolated (u, v); 0 where there are none.
    glm::dvec2 uv{0};
};

// The caller's judgement of which surfaces surely stop a shadow ray (opaque materials, other sources): a
// shadow ray that meets one before anything that might pass or bend light is blocked.
class ShadowBlockers {
public:
    virtual bool blocksShadows(const SurfaceId& id) const = 0;
    // Whether a blocker met anywhere on a shadow ray blocks it, whatever else lies before it.
    virtual bool blockersDecide() const = 0;

protected:
    ~ShadowBlockers() = default;
};

// What a shadow ray meets on its way to its target: nothing, a surface that surely blocks it, or something
// only a walk surface by surface can judge (glass, trans, antimatter, patterns, the target itself...).
enum class Occlusion { Clear, Blocked, Unsure };

class SceneGeometry {
public:
    // A scene with no instances or meshes.
    explicit SceneGeometry(std::vector<Surface> surfaces);
    explicit SceneGeometry(SceneLayout layout);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    // The nearest surface along the ray before ray.tmax, never the ray.leaving surface at its origin.
    std::optional<SurfaceHit> intersect(const Ray& ray) const;

    // Whether a shadow ray from ray.org along ray.dir reaches surface `target` at `distance` (infinity: it
    // leaves the scene), by Embree's occlusion query: no nearest hit, no exact hit point. Only surfaces before
    // the target count; those within rounding of it are Unsure, so that the walk decides as it always did.
    Occlusion occlusion(const Ray& ray, const SurfaceId& target, double distance, const ShadowBlockers& blockers) const;

    // The scene's own surfaces come first (ownSurfaces() of them), then those of octree prototypes.
    const std::vector<Surface>& surfaces() const { return layout_.surfaces; }
    int ownSurfaces() const { return layout_.ownSurfaces; }
    const std::vector<Prototype>& prototypes() const { return layout_.prototypes; }
    const std::vector<Placement>& placements() const { return layout_.placements; }
    // Polygons, rings and mesh triangles.
    bool isFlat(const SurfaceId& id) const {
        return id.triangle >= 0 || std::holds_alternative<Polygon>(surfaces()[id.surface].shape) ||
               std::holds_alternative<Ring>(surfaces()[id.surface].shape);
    }
    // The mesh a hit's triangle belongs to (nullptr for other surfaces).
    const Mesh* meshOf(const SurfaceId& id) const {
        return id.triangle < 0 ? nullptr : layout_.prototypes[layout_.placements[id.instance].prototype].mesh;
    }
    // The box of what sets the scene's scale: all surfaces and placed copies but those far larger than the
    // typical one (a ground 2000 km wide) or far from the rest (a ball 1e12 m away); all of them where
    // every one is such (empty box when there are none).
    const Bounds3& extent() const { return extent_; }
    // Where the world's float coordinates are offsets from: a point among the scene's surfaces, so that
    // lengths measured from it (rather than from (0, 0, 0)) are the same wherever the model stands.
    dvec3 origin() const;

private:
    struct Group;
    struct ShadowQuery;
    struct TraceContext;
    // A flat primitive in its prototype's coordinates: a polygon's triangle or a mesh triangle, and the
    // plane its hits lie on.
    struct FlatPiece {
        const dvec3* corner[3];
        dvec3 normal;
        const dvec3* onPlane;
    };
    std::vector<Bounds3> pieceBoxes(Group& group, int prototype) const;
    void buildGroup(Group& group);
    static bool floatPiece(const Group& group, const Bounds3& box);
    bool floatPolygon(const Group& group, int surface) const;
    void addPolygons(Group& group);
    void addMeshTriangles(Group& group);
    void addExactShapes(Group& group);
    void addPlacements(const std::vector<Bounds3>& items);
    Bounds3 placedBounds(const Placement& placement) const;
    static bool traceable(const Bounds3& box);
    bool hidden(const SurfaceId& id) const;
    const Group& groupOf(const SurfaceId& id) const;
    FlatPiece flatPiece(const SurfaceId& id, int triangle) const;
    std::optional<double> flatHit(const SurfaceId& id, const FlatPiece& piece, const Ray& world,
                                  std::optional<double> slack) const;
    static bool within(const FlatPiece& piece, const dvec3& q, double slack);
    std::optional<double> floatSlack(const SurfaceId& id, double t, const TraceContext& ctx) const;
    Ray localRay(const Ray& ray, int placement) const;
    void interpolateMesh(const SurfaceId& id, const Ray& local, SurfaceHit& hit) const;
    std::optional<ShapeHit> exactHit(const Group& group, unsigned prim, const SurfaceId& id, const Ray& world,
                                     double tmax) const;
    bool toEmbree(const Ray& ray, RTCRay& r, double& behind) const;
    // A float triangle Embree proposes, as the exact test decides it: its distance, surface, plane normal.
    struct Candidate {
        double t;
        SurfaceId id;
        dvec3 normal;
    };
    static std::optional<Candidate> floatCandidate(const RTCFilterFunctionNArguments* args, unsigned i,
                                                   const TraceContext& ctx);
    static void filterTriangle(const RTCFilterFunctionNArguments* args);
    static void filterShadowTriangle(const RTCFilterFunctionNArguments* args);
    static void exactBounds(const RTCBoundsFunctionArguments* args);
    static void exactIntersect(const RTCIntersectFunctionNArguments* args);
    static void exactOccluded(const RTCOccludedFunctionNArguments* args);

    SceneLayout layout_;
    std::vector<Group> groups_;  // [0]: the scene's own surfaces and the placements; [1 + k]: prototype k
    std::vector<double> placementShift_;  // per placement: |translation| of its float transform
    std::vector<bool> placementNear_;     // per placement: near the world's origin (LocalFrame::near)
    Bounds3 extent_;
    RTCDevice device_ = nullptr;
};

}  // namespace brume
