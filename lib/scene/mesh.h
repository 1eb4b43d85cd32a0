// Triangle meshes, as Radiance's mesh primitive places them: read from a compiled Radiance mesh (.rtm, the
// output of obj2mesh) or, as a Brume extension, from the Wavefront .obj file itself.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <istream>
#include <string>
#include <vector>

namespace brume {

struct Scene;

// A mesh in its own coordinates.
struct Mesh {
    std::vector<glm::dvec3> vertices;
    // Per vertex, both optional: a unit normal (zero when there is none) and local (u, v) coordinates (NaN
    // when there are none). A triangle is smoothed, or has Radiance's Lu Lv, only where all three of its
    // vertices have them. Empty when no vertex has any.
    std::vector<glm::vec3> normals;
    std::vector<glm::dvec2> uvs;
    // Vertex indices, counter-clockwise seen from the front (where the vertex normals point).
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<int> materials;  // per triangle: its material object in Scene::objects, -1 for void
    // A compiled mesh's bounding cube (what oconv bounds mesh objects by); size 0 for Wavefront meshes.
    glm::dvec3 cubeOrigin{0};
    double cubeSize = 0;
};

// Reads a compiled Radiance mesh; its materials are appended to `scene`. Throws Error ("name: what") on a
// malformed or truncated file.
Mesh readRadianceMesh(Scene& scene, std::istream& in, const std::string& name);

// The material object a usemtl (or group) name stands for, or -1 when undefined.
using MaterialLookup = std::function<int(const std::string& name)>;

// Reads Wavefront .obj text (v, vt, vn, f with negative indices and polygons, usemtl, g) as obj2mesh would
// compile it: faces with a usemtl name, else a group name, get that material (`lookup`; an undefined name
// is an error), others are void; no lookup makes all faces void (obj2mesh without -a). Throws Error
// ("name:line: what").
Mesh readWavefront(std::istream& in, const std::string& name, const MaterialLookup& lookup);

// Whether a mesh file is Wavefront text (named *.obj) rather than a compiled Radiance mesh.
bool isWavefrontName(const std::string& path);

}  // namespace brume
