// The scene's surfaces in Embree: polygons and mesh triangles as triangles, spheres, cones and rings as exact
// user geometry; each prototype (an instanced octree's surfaces, a mesh) in an Embree scene of its own, built
// once and placed by Embree instances. Embree finds the nearest candidate; the hit point and normal are then
// computed in double precision from the exact shape (in its prototype's coordinates for placed surfaces), so
// shading never sees float rounding.
#pragma once
#include <embree3/rtcore.h>

#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "geometry/scene_layout.h"
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
    // Bounding box of all surfaces in the world (empty box, min > max, when there are none).
    dvec3 boundsMin() const { return lo_; }
    dvec3 boundsMax() const { return hi_; }

private:
    struct Group;
    void buildGroup(Group& group, int prototype);
    void addPolygons(Group& group);
    void addMeshTriangles(Group& group);
    void addExactShapes(Group& group);
    void addPlacements();
    void placedBounds(const Placement& placement, dvec3& lo, dvec3& hi) const;
    bool traceable(const Placement& placement) const;
    void computeBounds();
    bool hidden(const SurfaceId& id) const;
    void plane(const SurfaceId& id, dvec3& normal, dvec3& point) const;
    bool meetsFlat(const SurfaceId& id, const Ray& ray) const;
    Ray localRay(const Ray& ray, int placement) const;
    double exactPlaneHit(const SurfaceId& id, const Ray& local, float embreeT, dvec3& normal) const;
    void interpolateMesh(const SurfaceId& id, const Ray& local, SurfaceHit& hit) const;
    std::optional<ShapeHit> exactHit(const SurfaceId& id, const Ray& world, float tfar) const;
    bool meetsTriangle(const SurfaceId& id, const Ray& ray) const;
    static SurfaceId candidate(const RTCFilterFunctionNArguments* args, unsigned i);
    static void filterTriangle(const RTCFilterFunctionNArguments* args);
    static void filterShadowTriangle(const RTCFilterFunctionNArguments* args);
    static void exactBounds(const RTCBoundsFunctionArguments* args);
    static void exactIntersect(const RTCIntersectFunctionNArguments* args);
    static void exactOccluded(const RTCOccludedFunctionNArguments* args);

    SceneLayout layout_;
    std::vector<Group> groups_;  // [0]: the scene's own surfaces and the placements; [1 + k]: prototype k
    dvec3 lo_, hi_;
    RTCDevice device_ = nullptr;
};

}  // namespace brume
