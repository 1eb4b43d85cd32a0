#include "scene/placed_files.h"

#include <fstream>

#include "scene/mesh.h"
#include "scene/octree.h"
#include "scene/raypath.h"

namespace brume {

namespace {

// An octree's objects appended to the scene, their modifiers shifted with them.
PlacedFile appendOctree(Scene& scene, const std::string& path) {
    Scene octree;
    readOctreeFile(octree, path);
    PlacedFile file{path, int(scene.objects.size()), 0, nullptr, octree.cube.value_or(OctreeCube{})};
    for (SceneObject& o : octree.objects) {
        if (o.modifier >= 0) o.modifier += file.firstObject;
        scene.add(std::move(o));
    }
    file.endObject = int(scene.objects.size());
    return file;
}

// A mesh file; a mesh object that has no modifier of its own (`user`) needs its usemtl names resolved.
PlacedFile appendMesh(Scene& scene, const std::string& path, int user, bool resolveNames) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(SourceLocation{path}, "cannot open mesh file");
    PlacedFile file{path, int(scene.objects.size()), 0, nullptr, {}};
    if (!isWavefrontName(path)) {
        file.mesh = std::make_shared<Mesh>(readRadianceMesh(scene, in, path));
    } else {
        MaterialLookup lookup = [&](const std::string& name) { return scene.modifierBefore(user, name); };
        file.mesh = std::make_shared<Mesh>(readWavefront(in, path, resolveNames ? lookup : nullptr));
    }
    file.endObject = int(scene.objects.size());
    return file;
}

}  // namespace

void loadPlacedFiles(Scene& scene) {
    std::unordered_map<std::string, int> loaded;  // by kind and path
    // Objects appended by a file are visited in turn, so instances inside instanced octrees load too.
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.type != "instance" && o.type != "mesh") continue;
        SourceLocation where = o.where;
        bool mesh = o.type == "mesh";
        if (o.strings.empty() || !o.integers.empty() || !o.reals.empty())
            throw Error(where,
                        "bad arguments for " + o.type + " \"" + o.name + "\": expected a file name and a transform");
        std::string path = findOnRayPath(o.strings[0]);
        if (path.empty())
            throw Error(where,
                        std::string("cannot find ") + (mesh ? "mesh" : "octree") + " file \"" + o.strings[0] + "\"");
        bool resolveNames = mesh && o.modifier < 0 && isWavefrontName(path);
        std::string key = o.type + (resolveNames ? "+materials:" : ":") + path;
        auto [it, added] = loaded.try_emplace(key, int(scene.placedFiles.size()));
        if (added) {
            scene.sources.push_back(path);
            try {
                scene.placedFiles.push_back(mesh ? appendMesh(scene, path, int(i), resolveNames)
                                                 : appendOctree(scene, path));
            } catch (const Error& e) {
                throw Error(where, e.what());
            }
        }
        scene.placedFileOf[int(i)] = it->second;
    }
}

}  // namespace brume
