// The scene's surfaces as SceneGeometry builds them: the scene's own, and prototypes (the surfaces of an
// instanced octree, or a mesh) that instance and mesh objects place in the world, each built once however
// many placements copy it.
#pragma once
#include <vector>

#include "geometry/surface.h"
#include "geometry/transform.h"
#include "scene/scene.h"

namespace brume {

// The surfaces of an instanced octree (a range of SceneLayout::surfaces), or a mesh.
struct Prototype {
    int firstSurface = 0, endSurface = 0;
    const Mesh* mesh = nullptr;
};

// A copy of a prototype placed in the world by an instance or mesh object. Nested instances are flattened:
// one placement per path of instance objects down to the prototype.
struct Placement {
    int prototype;
    Transform transform;  // prototype coordinates → world
    Transform inverse;
    int object;  // the instance or mesh object that places it (the innermost of the path)
    // As Radiance's instances and meshes: the outermost object of the path that has a modifier, whose
    // modifier replaces every material of the prototype; -1 when none has one.
    int modifierObject;
    // The transform patterns apply at its surfaces (Radiance's ray transform): that of the path's objects
    // outside modifierObject, or of the whole path when no object has a modifier.
    Transform patternTransform;
};

struct SceneLayout {
    std::vector<Surface> surfaces;  // the scene's own first, then those of the octree prototypes
    int ownSurfaces = 0;
    std::vector<Prototype> prototypes;  // one per Scene::placedFiles entry, in the same order
    std::vector<Placement> placements;
};

// The layout of a scene whose placed files are loaded (loadPlacedFiles). Throws Error (file:line) on
// malformed surfaces and transforms, and on an instance that holds itself. Surfaces with a void modifier are
// dropped, except in prototypes (see Surface::voidModifier).
SceneLayout layoutScene(const Scene& scene);

// The transform of an instance or mesh object (its arguments after the file name, all of them). Throws
// Error (file:line) when they are not a transform.
Transform objectTransform(const SceneObject& o);

}  // namespace brume
