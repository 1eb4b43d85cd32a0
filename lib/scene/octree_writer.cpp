#include "scene/octree_writer.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace brume {

namespace {

constexpr int kObjectSize = 4;  // bytes per object index, as Radiance's 32-bit OBJECT
constexpr int kMagic = 4 * 8 + 251 + kObjectSize;

void putInteger(std::ostream& out, long value, int size) {
    for (int shift = 8 * (size - 1); shift >= 0; shift -= 8) out.put(static_cast<char>((value >> shift) & 0xff));
}

void putString(std::ostream& out, const std::string& s) { out.write(s.c_str(), static_cast<std::streamsize>(s.size() + 1)); }

// Radiance's portable real: frexp's mantissa times 2^31 − 1 (truncated), and the exponent; overflow
// saturates and underflow gives 0, as Radiance's putflt.
void putReal(std::ostream& out, double x) {
    int exponent = 0;
    long mantissa = static_cast<long>(std::frexp(x, &exponent) * 2147483647.0);
    if (exponent > 127) {
        mantissa = mantissa > 0 ? 2147483647L : -2147483647L;
        exponent = 127;
    } else if (exponent < -128) {
        mantissa = 0;
        exponent = 0;
    }
    putInteger(out, mantissa, 4);
    putInteger(out, exponent, 1);
}

std::string cubeNumber(double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.12g", x);
    return text;
}

void putNodes(std::ostream& out, const std::vector<OctreeNode>& nodes) {
    for (const OctreeNode& node : nodes) {
        if (node.tree) {
            out.put(2);
        } else if (node.set.empty()) {
            out.put(0);
        } else {
            out.put(1);
            putInteger(out, static_cast<long>(node.set.size()), kObjectSize);
            for (int object : node.set) putInteger(out, object, kObjectSize);
        }
    }
}

// The objects themselves: the names of the types used, in order of first use, then each object by its
// type's index.
void putObjects(std::ostream& out, const Scene& scene, size_t count) {
    std::unordered_map<std::string, int> typeIndex;
    std::vector<const std::string*> types;
    for (size_t i = 0; i < count; ++i)
        if (typeIndex.try_emplace(scene.objects[i].type, static_cast<int>(types.size())).second)
            types.push_back(&scene.objects[i].type);
    if (types.size() > static_cast<size_t>(SCHAR_MAX)) throw Error(SourceLocation{}, "too many object types to freeze");
    for (const std::string* type : types) putString(out, *type);
    putString(out, "");
    for (size_t i = 0; i < count; ++i) {
        const SceneObject& o = scene.objects[i];
        if (!o.integers.empty())
            throw Error(o.where, "cannot freeze " + o.type + " \"" + o.name + "\": it has integer arguments");
        putInteger(out, typeIndex.at(o.type), 1);
        putInteger(out, o.modifier, kObjectSize);
        putString(out, o.name);
        putInteger(out, static_cast<long>(o.strings.size()), 2);
        for (const std::string& s : o.strings) putString(out, s);
        putInteger(out, static_cast<long>(o.reals.size()), 2);
        for (double x : o.reals) putReal(out, x);
    }
    putInteger(out, -1, 1);
}

}  // namespace

void writeOctree(std::ostream& out, const OctreeContents& octree) {
    for (const std::string& line : octree.headerLines) out << line << '\n';
    out << "FORMAT=Radiance_octree\n\n";
    putInteger(out, kMagic, 2);
    for (double x : octree.cube.origin) putString(out, cubeNumber(x));
    putString(out, cubeNumber(octree.cube.size));
    for (const std::string& file : octree.files) putString(out, file);
    putString(out, "");
    putInteger(out, static_cast<long>(octree.objectCount), kObjectSize);
    putNodes(out, octree.nodes);
    if (octree.files.empty()) putObjects(out, *octree.scene, octree.objectCount);
}

}  // namespace brume
