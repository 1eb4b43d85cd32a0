// The octree Radiance's oconv builds over a scene, for octree files other programs (Radiance's rtrace among
// them) trace through: a cube around the scene by oconv's rule, divided while a cube holds more than a
// limit of objects, each leaf listing every surface, instance and mesh that may meet it. Brume's own
// programs never use these nodes (they build their own acceleration structure), only the cube.
#pragma once
#include <optional>
#include <vector>

#include "scene/octree_writer.h"
#include "scene/scene.h"

namespace brume {

// Radiance's OMARGIN: what oconv widens the scene's bounds by on each side (and a cube given with -b).
constexpr double kOctreeMargin = 1e-5;

struct OctreeBuildOptions {
    size_t objectLimit = 6;  // oconv -n: a cube holding more is divided...
    int resolution = 16384;  // oconv -r: ...unless its children would be smaller than the cube's size / this
    // oconv -b: the cube to use (it must hold the scene); by default the scene's bounds with a margin.
    std::optional<OctreeCube> cube;
};

struct BuiltOctree {
    OctreeCube cube;
    std::vector<OctreeNode> nodes;
    // Leaves that would list more than kMaxOctreeSet objects (Radiance's limit) list only the first ones:
    // the first object left out of one, or -1 when none was.
    int overflowObject = -1;
};

// Builds the octree over objects [0, count) of `scene`, whose placed files (loadPlacedFiles) give the
// bounds of instances and meshes. Modifiers and sources take no place in it. Throws Error for malformed
// surfaces or transforms, and when options.cube does not hold the scene.
BuiltOctree buildOctree(const Scene& scene, size_t count, const OctreeBuildOptions& options = {});

}  // namespace brume
