// Reading the octree files Radiance's oconv writes. Only the scene is taken from them (Brume builds its
// own acceleration structure): a normal octree lists the scene files it was made from, which are read
// again; a frozen one (oconv -f) holds the objects themselves in binary.
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "scene/reader.h"
#include "scene/scene.h"

namespace brume {

// Whether the stream starts with an information header saying FORMAT=Radiance_octree. Leaves the
// stream where it was (it must be seekable).
bool isOctree(std::istream& in);
// Appends an octree's objects to `scene` and sets its headerLines and cube; `name` is used in messages.
// The scene files a normal octree lists are opened as rtrace does: relative to the current directory
// (not the octree's), names starting with '!' being commands if `options` allow them (its
// searchRayPath is ignored). `listed`, when given, receives the names of those files (none if frozen).
void readOctree(Scene& scene, std::istream& in, const std::string& name, const ReadOptions& options = {},
                std::vector<std::string>* listed = nullptr);
void readOctreeFile(Scene& scene, const std::string& path, std::vector<std::string>* listed = nullptr);

}  // namespace brume
