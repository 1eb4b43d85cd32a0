// Compiled Radiance meshes, as obj2mesh writes them (facts from Radiance's mesh.h, writemesh.c, readmesh.c,
// mesh.c and dircode.c; the shared binary parts are described in binary_input.h):
//   information header with FORMAT=Radiance_tmesh;
//   magic: 2-byte integer 319 + objsize;
//   bounding cube: origin x, y, z and size as text; then the (u, v) limits as reals: u min, u max, v min, v max;
//   the mesh's octree (skipped here), its materials as frozen objects, a 4-byte patch count and the patches.
// A patch: 1-byte flags (1 positions, 2 normals, 4 uv), 2-byte vertex count (1 to 256), per vertex three
// 4-byte unsigned positions in the cube (x = origin + (i + 0.5) · size / 2³²), then if flagged a 4-byte
// direction code per vertex (0: no normal), then two 4-byte uv codes per vertex (u = min + (i + 0.5) ·
// (max − min) / 2³², no uv when the first is 0); a 2-byte count (≤ 512) of local triangles of three 1-byte
// vertex indices; a 2-byte material count, more than 1 followed by a 2-byte material per local triangle, else
// by the one material of all; joiner triangles (≤ 256) with one vertex in another patch: 4-byte vertex id,
// two 1-byte local vertices, 2-byte material; double joiners (≤ 256): two 4-byte vertex ids, one 1-byte
// local vertex, 2-byte material. A vertex id is patch · 256 + index. Materials count from the mesh's first
// material object, -1 being void; a mesh with materials may have no void triangle.
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "scene/binary_input.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace brume {

namespace {

constexpr int kMagic = 1 * 8 + 311;  // Radiance's MESHMAGIC, to which objsize is added
constexpr int kMaxObjectSize = 8;
constexpr const char* kFormat = "Radiance_tmesh";
constexpr double kTwoTo32 = 4294967296.0;

// Radiance's 4-byte direction code: two of the three components, 13 bits each in units of 1/11584.5, the
// third from the unit length; bits 0-2 negate x, y, z; bit 3 says the first stored component is x (else y),
// bit 4 that the second is z (else the remaining one of x and y, and the derived one is z).
glm::vec3 decodeDirection(uint32_t code) {
    constexpr double kScale = 11584.5;
    double first = (code >> 5 & 0x1fff) / kScale, second = (code >> 18 & 0x1fff) / kScale;
    double derived = std::sqrt(std::max(0.0, 1 - first * first - second * second));
    bool firstIsX = code & 010, secondIsZ = code & 020;
    int a = firstIsX ? 0 : 1, other = firstIsX ? 1 : 0;
    glm::dvec3 d(0);
    d[a] = first;
    d[secondIsZ ? 2 : other] = second;
    d[secondIsZ ? other : 2] = derived;
    for (int i = 0; i < 3; ++i)
        if (code & (1u << i)) d[i] = -d[i];
    return glm::vec3(d);
}

struct Header {
    glm::dvec3 origin;
    double size;
    double uvMin[2], uvMax[2];
};

class RtmReader {
public:
    RtmReader(Scene& scene, std::istream& in, const std::string& name)
        : scene_(scene), in_(in), input_(in, name, "mesh") {}

    Mesh read() {
        readFileHeader();
        skipOctreeNodes(input_, objectSize_);
        firstMaterial_ = int(scene_.objects.size());
        materialCount_ = int(readFrozenObjects(scene_, input_, objectSize_));
        for (int i = firstMaterial_; i < firstMaterial_ + materialCount_; ++i)
            if (!isModifierType(scene_.objects[i].type))
                input_.fail("non-modifier in mesh (" + scene_.objects[i].type + " \"" + scene_.objects[i].name + "\")");
        long patches = input_.integer(4);
        if (patches <= 0 || patches > (1L << 22)) input_.fail("bad number of mesh patches");
        for (long p = 0; p < patches; ++p) readPatch();
        return resolve();
    }

private:
    void readFileHeader() {
        auto header = readInfoHeader(in_, SIZE_MAX);
        if (!header) input_.fail("not a mesh (no information header)");
        for (const std::string& line : *header)
            if (auto format = formatOf(line); format && *format != kFormat)
                input_.fail("not a mesh (FORMAT=" + *format + ")");
        objectSize_ = int(input_.integer(2) - kMagic);
        if (objectSize_ <= 0 || objectSize_ > kMaxObjectSize) input_.fail("incompatible mesh format");
        for (int i = 0; i < 3; ++i) header_.origin[i] = input_.textNumber("bounds");
        header_.size = input_.textNumber("bounds");
        mesh_.cubeOrigin = header_.origin;
        mesh_.cubeSize = header_.size;
        if (!(header_.size > 1e-6)) input_.fail("illegal octree bounds in mesh");
        if (glm::length(header_.origin) + header_.size > 1e18)
            input_.fail("mesh beyond ±1e18, where rays cannot be traced");
        for (int i = 0; i < 2; ++i) header_.uvMin[i] = input_.real(), header_.uvMax[i] = input_.real();
    }

    // A 2-byte count within [0, max].
    int count(long max, const char* what) {
        long n = input_.integer(2);
        if (n < 0 || n > max) input_.fail(std::string("bad number of ") + what);
        return int(n);
    }

    void readPatch() {
        long flags = input_.integer(1);
        if (!(flags & 1) || (flags & ~7L)) input_.fail("bad patch flags");
        int n = count(256, "patch vertices");
        if (n == 0) input_.fail("bad number of patch vertices");
        size_t first = mesh_.vertices.size();
        patchStart_.push_back(uint32_t(first));
        for (int i = 0; i < n; ++i) {
            glm::dvec3 v;
            for (int k = 0; k < 3; ++k)
                v[k] = header_.origin[k] + (uint32_t(input_.integer(4)) + 0.5) * (header_.size / kTwoTo32);
            mesh_.vertices.push_back(v);
        }
        if (flags & 2) readNormals(first, n);
        if (flags & 4) readUvs(first, n);
        uint32_t patch = uint32_t(patchStart_.size() - 1);
        readLocalTriangles(patch, n);
        for (int j = count(256, "joiner triangles"); j > 0; --j) {
            uint32_t a = uint32_t(input_.integer(4));
            uint32_t b = local(patch, n), c = local(patch, n);
            add({a, b, c}, material());
        }
        for (int j = count(256, "double joiner triangles"); j > 0; --j) {
            uint32_t a = uint32_t(input_.integer(4)), b = uint32_t(input_.integer(4));
            uint32_t c = local(patch, n);
            add({a, b, c}, material());
        }
    }

    void readNormals(size_t first, int n) {
        mesh_.normals.resize(mesh_.vertices.size());
        for (int i = 0; i < n; ++i)
            if (uint32_t code = uint32_t(input_.integer(4))) mesh_.normals[first + i] = decodeDirection(code);
    }

    void readUvs(size_t first, int n) {
        if (header_.uvMax[0] - header_.uvMin[0] <= 1e-6 || header_.uvMax[1] - header_.uvMin[1] <= 1e-6)
            input_.fail("unreferenced uv coordinates");
        mesh_.uvs.resize(mesh_.vertices.size(), glm::dvec2(std::numeric_limits<double>::quiet_NaN()));
        for (int i = 0; i < n; ++i) {
            uint32_t u = uint32_t(input_.integer(4)), v = uint32_t(input_.integer(4));
            if (u == 0) continue;
            mesh_.uvs[first + i] = {header_.uvMin[0] + (header_.uvMax[0] - header_.uvMin[0]) * (u + 0.5) / kTwoTo32,
                                    header_.uvMin[1] + (header_.uvMax[1] - header_.uvMin[1]) * (v + 0.5) / kTwoTo32};
        }
    }

    void readLocalTriangles(uint32_t patch, int n) {
        int count = this->count(512, "local triangles");
        std::vector<std::array<uint32_t, 3>> local(count);
        for (auto& t : local)
            for (uint32_t& v : t) v = this->local(patch, n);
        bool each = input_.integer(2) > 1;
        int sole = each ? 0 : material();
        for (const auto& t : local) add({t[0], t[1], t[2]}, each ? material() : sole);
    }

    // The id of a vertex of this patch (of n vertices) given by its 1-byte index.
    uint32_t local(uint32_t patch, int n) {
        int v = input_.byte();
        if (v >= n) input_.fail("bad local triangle index");
        return patch << 8 | uint32_t(v);
    }

    int material() {
        long m = input_.integer(2);
        if (materialCount_ == 0) return -1;
        if (m < 0 || m >= materialCount_) input_.fail("bad triangle material");
        return firstMaterial_ + int(m);
    }

    // A triangle as read: its vertex ids, resolved to indices once all patches are in (resolve()).
    void add(std::array<uint32_t, 3> ids, int material) {
        mesh_.triangles.push_back(ids);
        mesh_.materials.push_back(material);
    }

    // Vertex ids to indices, now that every patch is known (joiners may refer to later patches).
    Mesh resolve() {
        for (auto& t : mesh_.triangles)
            for (uint32_t& v : t) v = index(v);
        if (mesh_.triangles.empty()) input_.fail("mesh has no triangles");
        // Patches without normals or uv after ones with them.
        if (!mesh_.normals.empty()) mesh_.normals.resize(mesh_.vertices.size());
        if (!mesh_.uvs.empty())
            mesh_.uvs.resize(mesh_.vertices.size(), glm::dvec2(std::numeric_limits<double>::quiet_NaN()));
        return std::move(mesh_);
    }

    uint32_t index(uint32_t id) const {
        uint32_t patch = id >> 8;
        if (patch >= patchStart_.size()) input_.fail("bad joiner triangle vertex");
        uint32_t end = patch + 1 < patchStart_.size() ? patchStart_[patch + 1] : uint32_t(mesh_.vertices.size());
        uint32_t i = patchStart_[patch] + (id & 0xff);
        if (i >= end) input_.fail("bad joiner triangle vertex");
        return i;
    }

    Scene& scene_;
    std::istream& in_;
    BinaryInput input_;
    Header header_{};
    int objectSize_ = 0, firstMaterial_ = 0, materialCount_ = 0;
    std::vector<uint32_t> patchStart_;  // index of each patch's first vertex
    Mesh mesh_;
};

}  // namespace

Mesh readRadianceMesh(Scene& scene, std::istream& in, const std::string& name) {
    return RtmReader(scene, in, name).read();
}

}  // namespace brume
