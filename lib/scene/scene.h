// The scene as Radiance describes it: a list of objects, each "modifier type identifier" with string,
// integer and real arguments, read from .rad text or an octree. Nothing is interpreted here: the
// geometry, material and light modules turn objects into shapes and BSDFs.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/mesh.h"
#include "util/error.h"

namespace brume {

// One Radiance object, as written in the scene.
struct SceneObject {
    std::string type;        // "plastic", "polygon", ... (never "alias": aliases are stored resolved)
    std::string name;        // its identifier
    int modifier = -1;       // index of the modifier object in Scene::objects, -1 for void
    std::vector<std::string> strings;
    std::vector<long> integers;
    std::vector<double> reals;
    SourceLocation where;    // where it was defined (file:line of its first token)
};

// Whether objects of this type may modify others. Radiance's surfaces (polygon, sphere, source, ...) and
// volumes (instance, mesh), and Brume's smoke, may not, so they never shadow a modifier of the same name;
// every other type, including ones unknown here, may.
bool isModifierType(std::string_view type);

// Radiance's material types (plastic, metal, trans, mirror, glass, dielectric, the function and data BRDFs,
// BSDF), and among them the BRDFs given by function files (plasfunc, metfunc, transfunc, plasdata, …).
bool isMaterialType(const std::string& type);
bool isFunctionBrdfType(const std::string& type);
// Radiance's surface types: sphere, bubble, polygon, cone, cup, cylinder, tube, ring.
bool isSurfaceType(const std::string& type);
// Radiance's emitter types: light, spotlight, glow, illum.
bool isEmitterType(const std::string& type);

// The bounding cube oconv stored in an octree; rtrace scales some parameters (-ar) by its size.
struct OctreeCube {
    std::array<double, 3> origin{};
    double size = 0;
};

// A file that instance or mesh objects place in the scene (an octree, or a mesh), loaded once however many
// objects name it. Its objects (an octree's scene, a mesh's materials) follow the scene's own in
// Scene::objects.
struct PlacedFile {
    std::string path;
    int firstObject = 0, endObject = 0;
    std::shared_ptr<const Mesh> mesh;  // a mesh's triangles; null for an octree
    OctreeCube cube;                   // an octree's bounding cube (what oconv bounds its instances by)
};

struct Scene {
    std::vector<SceneObject> objects;  // in definition order; modifiers always precede their users
    // Latest definition of each modifier identifier, used to resolve modifiers as the scene is read
    // (Radiance semantics: a modifier refers to the most recent modifier of that name defined before
    // it; surfaces of the same name do not count; and, as in Radiance, an identical redefinition
    // leaves the earlier one in place, so that text and frozen octrees give the same indices).
    std::unordered_map<std::string, int> lastDefinition;
    // The files the scene was read from, in order (for headers and cache validation).
    std::vector<std::string> sources;
    // Read from an octree only: its information header lines, without newlines, except the FORMAT=
    // line (exactly what rtrace -h+ copies to its output header), and its bounding cube.
    std::vector<std::string> headerLines;
    std::optional<OctreeCube> cube;
    // The octrees and meshes of instance and mesh objects (loadPlacedFiles in placed_files.h), and which
    // one each such object names.
    std::vector<PlacedFile> placedFiles;
    std::unordered_map<int, int> placedFileOf;  // instance or mesh object → index in placedFiles

    // The objects of the scene itself come first; those of placed files follow them.
    size_t ownObjects() const { return placedFiles.empty() ? objects.size() : size_t(placedFiles.front().firstObject); }

    // Appends `object`, indexing it in lastDefinition if it is a modifier; returns its index.
    int add(SceneObject object);
    // The index of the latest modifier named `name`, or -1.
    int findModifier(const std::string& name) const;
    // The modifier named `name` that object `object` refers to in its arguments (Radiance's lastmod): the
    // latest one defined before it. -1 if there is none.
    int modifierBefore(int object, const std::string& name) const;

private:
    bool sameDefinition(int a, int b) const;
};

}  // namespace brume
