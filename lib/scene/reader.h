// Reading Radiance scene descriptions (.rad text, octrees) into a Scene.
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace brume {

struct ReadOptions {
    // Run "!command" lines (and "!command" file names) through /bin/sh and read their output; when
    // false they are an error (for untrusted input, e.g. fuzzing).
    bool allowCommands = true;
    // Look file names up along RAYPATH; when false, relative names are relative to the current
    // directory (as rtrace opens the files an octree lists).
    bool searchRayPath = true;
};

// Appends the objects of a .rad file, found along RAYPATH, to `scene`. "-" reads standard input; a name
// starting with '!' is a command whose output is read (as in Radiance's oconv).
void readSceneFile(Scene& scene, const std::string& path, const ReadOptions& options = {});
// Appends the objects of .rad text; `name` is the file name used in error messages.
void readSceneText(Scene& scene, std::istream& in, const std::string& name, const ReadOptions& options = {});
// The scene named on a command line: one octree (frozen or not) or any number of .rad files ("-" for
// standard input), with the files its instance and mesh objects place (loadPlacedFiles). A file is an
// octree if its information header says FORMAT=Radiance_octree.
Scene loadScene(const std::vector<std::string>& paths);

}  // namespace brume
