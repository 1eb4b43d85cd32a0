// Writing octree files as Radiance's oconv does, readable by Radiance's programs and Brume's (the format is
// described in octree.cpp and binary_input.h).
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace brume {

// Radiance's limit on the objects a leaf may list (its MAXSET).
constexpr size_t kMaxOctreeSet = 511;

// One node of an octree in pre-order: a tree node (its eight children follow it, child i's origin being
// offset by half the size along x if i & 1, y if i & 2, z if i & 4), or a leaf listing the objects that
// may meet its cube in increasing order (none: an empty node).
struct OctreeNode {
    bool tree = false;
    std::vector<int> set;
};

struct OctreeContents {
    // The information header's lines, "#?RADIANCE" first, without the FORMAT= line (as Scene::headerLines).
    std::vector<std::string> headerLines;
    OctreeCube cube;
    // The scene files a normal octree lists (read again by whoever loads it); none for a frozen octree,
    // which holds the objects themselves.
    std::vector<std::string> files;
    const Scene* scene = nullptr;  // objects [0, objectCount) are the octree's
    size_t objectCount = 0;
    std::vector<OctreeNode> nodes;
};

// Writes the octree. Throws Error (file:line of the object) for an object that cannot be frozen: one with
// integer arguments, which Radiance's files have no place for.
void writeOctree(std::ostream& out, const OctreeContents& octree);

}  // namespace brume
