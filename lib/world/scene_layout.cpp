#include "world/scene_layout.h"

#include <algorithm>

#include "world/scene_surfaces.h"

namespace brume {

namespace {

// The surfaces of objects [begin, end). Void ones are kept only in prototypes, where an instance's modifier
// may show them; the scene's own are never seen (Radiance drops them too).
void addSurfaces(const Scene& scene, int begin, int end, bool prototype, std::vector<Surface>& out) {
    for (int i = begin; i < end; ++i) {
        const SceneObject& o = scene.objects[i];
        if (!isSurfaceType(o.type) || (o.modifier < 0 && !prototype)) continue;
        auto surface = makeSurface(scene, i);
        if (!surface) continue;
        if (!withinTraceableRange(surface->shape)) {
            warn(o.where.str() + ": " + o.type + " \"" + o.name +
                 "\" reaches beyond ±1e18, where rays cannot be traced; dropped");
            continue;
        }
        surface->voidModifier = o.modifier < 0;
        out.push_back(std::move(*surface));
    }
}

// Places the instances and meshes among objects [begin, end), and those inside them, under `outer` (the
// transform, modifier object and pattern transform of the path so far).
class Placer {
public:
    Placer(const Scene& scene, SceneLayout& layout) : scene_(scene), layout_(layout) {}

    void place(int begin, int end, const Placement& outer) {
        for (int i = begin; i < end; ++i) {
            const SceneObject& o = scene_.objects[i];
            if (o.type != "instance" && o.type != "mesh") continue;
            auto found = scene_.placedFileOf.find(i);
            if (found == scene_.placedFileOf.end())
                throw Error(o.where, "the file of " + o.type + " \"" + o.name + "\" is not loaded");
            int file = found->second;
            Placement p = placementOf(i, file, outer);
            layout_.placements.push_back(p);
            if (o.type == "mesh") continue;
            if (std::find(path_.begin(), path_.end(), file) != path_.end())
                throw Error(o.where,
                            "instance \"" + o.name + "\" holds itself (" + scene_.placedFiles[file].path + ")");
            path_.push_back(file);
            place(scene_.placedFiles[file].firstObject, scene_.placedFiles[file].endObject, p);
            path_.pop_back();
        }
    }

private:
    Placement placementOf(int object, int file, const Placement& outer) const {
        const SceneObject& o = scene_.objects[object];
        Transform t = objectTransform(o).then(outer.transform);
        Placement p{file, t, t.inverse(), object, outer.modifierObject, outer.patternTransform};
        if (outer.modifierObject < 0) {
            // Radiance: the outermost modifier wins, and patterns then see the coordinates outside its object.
            if (o.modifier >= 0)
                p.modifierObject = object, p.patternTransform = outer.transform;
            else
                p.patternTransform = t;
        }
        return p;
    }

    const Scene& scene_;
    SceneLayout& layout_;
    std::vector<int> path_;  // placed files of the instances being placed, to refuse cycles
};

}  // namespace

SceneLayout layoutScene(const Scene& scene) {
    SceneLayout layout;
    addSurfaces(scene, 0, int(scene.ownObjects()), false, layout.surfaces);
    layout.ownSurfaces = int(layout.surfaces.size());
    for (const PlacedFile& file : scene.placedFiles) {
        Prototype p;
        p.mesh = file.mesh.get();
        p.firstSurface = int(layout.surfaces.size());
        if (!p.mesh) addSurfaces(scene, file.firstObject, file.endObject, true, layout.surfaces);
        p.endSurface = int(layout.surfaces.size());
        layout.prototypes.push_back(p);
    }
    Placer(scene, layout).place(0, int(scene.ownObjects()), Placement{-1, {}, {}, -1, -1, {}});
    return layout;
}

Transform objectTransform(const SceneObject& o) {
    std::span<const std::string> args(o.strings.begin() + 1, o.strings.end());
    ParsedTransform parsed = parseTransform(args);
    if (parsed.used != args.size()) throw Error(o.where, "bad transform for " + o.type + " \"" + o.name + "\"");
    return parsed.transform;
}

}  // namespace brume
