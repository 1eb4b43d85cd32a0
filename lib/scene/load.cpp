// loadScene (declared in reader.h): octree or .rad files, told apart by their content.
#include <fstream>
#include <iostream>
#include <sstream>

#include "scene/octree.h"
#include "scene/placed_files.h"
#include "scene/reader.h"

namespace brume {

namespace {

// Octrees are opened as given, never searched for (as rtrace does).
bool isOctreeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return in && isOctree(in);
}

// Standard input cannot be sniffed and rewound in place, so it is read whole first.
void readStandardInput(Scene& scene, bool only) {
    std::stringstream text;
    text << std::cin.rdbuf();
    if (!isOctree(text)) {
        scene.sources.push_back("-");
        return readSceneText(scene, text, "standard input");
    }
    if (!only) throw Error("standard input: an octree must be the only scene argument");
    readOctree(scene, text, "standard input");
}

}  // namespace

Scene loadScene(const std::vector<std::string>& paths) {
    if (paths.empty()) throw Error("no scene files or octree given");
    Scene scene;
    for (const std::string& path : paths) {
        if (path == "-") {
            readStandardInput(scene, paths.size() == 1);
        } else if (!path.starts_with('!') && isOctreeFile(path)) {
            // Scene files may follow an octree, as oconv -i adds them to one (rfluxmtx's receivers).
            if (&path != &paths.front())
                throw Error(SourceLocation{path}, "an octree must be the first scene argument, and the only octree");
            readOctreeFile(scene, path);
        } else {
            // Files named on the command line are opened as given when they exist, like oconv's;
            // only names not found there are looked up along RAYPATH.
            bool here = std::ifstream(path).good();
            readSceneFile(scene, path, ReadOptions{.searchRayPath = !here});
        }
    }
    loadPlacedFiles(scene);
    return scene;
}

}  // namespace brume
