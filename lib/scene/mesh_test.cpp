#include "scene/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <sstream>

#include "scene/placed_files.h"
#include "scene/reader.h"
#include "scene/scene.h"
#include "scene_text.h"

namespace brume {
namespace {

const std::string kDir = std::string(BRUME_TEST_DATA) + "/radiance_instances/";

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Mesh wavefront(const std::string& text, const MaterialLookup& lookup = nullptr) {
    std::istringstream in(text);
    return readWavefront(in, "t.obj", lookup);
}

std::string wavefrontError(const std::string& text, const MaterialLookup& lookup = nullptr) {
    try {
        wavefront(text, lookup);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// Triangles by their centroid (rounded to 1e-6), so that meshes listing them in different orders compare.
std::map<std::array<long, 3>, int> byCentroid(const Mesh& m) {
    std::map<std::array<long, 3>, int> out;
    for (int t = 0; t < int(m.triangles.size()); ++t) {
        glm::dvec3 c(0);
        for (uint32_t v : m.triangles[t]) c += m.vertices[v] / 3.0;
        out[{std::lround(c.x * 1e6), std::lround(c.y * 1e6), std::lround(c.z * 1e6)}] = t;
    }
    return out;
}

// `rtm` is obj2mesh's compilation of `obj` (with the materials of `materials`): the same triangles (vertices
// within the 32-bit grid of the mesh's cube, normals within Radiance's 4-byte direction code, (u, v) within
// their grid), wound the same way, with the same materials.
void expectCompilationOf(const std::string& dir, const std::string& obj, const std::string& rtm,
                         const std::string& materials, size_t materialCount) {
    Scene rtmScene;
    std::istringstream rtmText(fileText(dir + rtm));
    Mesh compiled = readRadianceMesh(rtmScene, rtmText, rtm);
    Scene objScene;
    std::istringstream materialText(fileText(dir + materials));
    readSceneText(objScene, materialText, materials);
    Mesh read = wavefront(fileText(dir + obj), [&](const std::string& n) { return objScene.findModifier(n); });

    ASSERT_EQ(compiled.triangles.size(), read.triangles.size());
    ASSERT_EQ(rtmScene.objects.size(), materialCount);  // carried by the mesh
    auto compiledAt = byCentroid(compiled);
    for (auto [key, t] : byCentroid(read)) {
        ASSERT_TRUE(compiledAt.count(key)) << "triangle " << t;
        int c = compiledAt[key];
        const auto &a = read.triangles[t], &b = compiled.triangles[c];
        int shift = 0;  // the same corners, possibly rotated
        while (shift < 3 && glm::length(read.vertices[a[0]] - compiled.vertices[b[shift]]) > 1e-9) ++shift;
        ASSERT_LT(shift, 3) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            uint32_t u = a[k], v = b[(k + shift) % 3];
            EXPECT_LT(glm::length(read.vertices[u] - compiled.vertices[v]), 1e-9);
            bool smooth = !read.normals.empty() && read.normals[u] != glm::vec3(0);
            ASSERT_EQ(smooth, compiled.normals[v] != glm::vec3(0)) << "triangle " << t;
            if (smooth) {
                EXPECT_LT(glm::length(read.normals[u] - compiled.normals[v]), 2e-4f);
            }
            ASSERT_EQ(std::isnan(read.uvs[u].x), std::isnan(compiled.uvs[v].x));  // the vault's ends have none
            if (!std::isnan(read.uvs[u].x)) {
                EXPECT_LT(glm::length(read.uvs[u] - compiled.uvs[v]), 1e-8);
            }
        }
        EXPECT_EQ(objScene.objects[read.materials[t]].name, rtmScene.objects[compiled.materials[c]].name);
    }
}

}  // namespace

// The vault of the Radiance comparison (one patch), and a grid whose triangles join two patches.
TEST(Mesh, RadianceMeshHoldsWhatObj2meshCompiledFromTheWavefrontFile) {
    expectCompilationOf(kDir, "vault.obj", "vault.rtm", "materials.rad", 2);
    expectCompilationOf(std::string(BRUME_TEST_DATA) + "/mesh/", "grid.obj", "grid.rtm", "ground.rad", 1);
}

TEST(Mesh, WavefrontFacesTakeRelativeIndicesAndSplitPolygons) {
    Mesh m = wavefront(
        "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 1 0\nv 0 2 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\n"
        "f -5/1 -4/2 -3/3\n"  // relative indices, with uv
        "f 1 2 3 4 5\n");     // a concave pentagon
    ASSERT_EQ(m.triangles.size(), 1u + 3u);
    EXPECT_TRUE(m.normals.empty());
    ASSERT_EQ(m.uvs.size(), m.vertices.size());
    EXPECT_EQ(m.uvs[m.triangles[0][2]], glm::dvec2(1, 1));
    EXPECT_TRUE(std::isnan(m.uvs[m.triangles[1][0]].x));  // the pentagon has no uv
    double area = 0;
    for (const auto& t : m.triangles) {
        glm::dvec3 n = glm::cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
        EXPECT_GT(n.z, 0);  // every triangle wound as its face
        area += 0.5 * n.z;
    }
    EXPECT_NEAR(area, 2.0 + 3.0, 1e-12);
}

// obj2mesh's rules: normals that do not bend a triangle are dropped; a triangle whose normals all point behind
// it is turned around; a normal is unit whatever its length in the file.
TEST(Mesh, WavefrontNormalsFollowObj2mesh) {
    Mesh flat = wavefront("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 3\nf 1//1 2//1 3//1\n");
    EXPECT_TRUE(flat.normals.empty());
    Mesh turned = wavefront("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn .1 0 -1\nvn 0 .1 -1\nf 1//1 2//2 3//1\n");
    ASSERT_EQ(turned.triangles.size(), 1u);
    const auto& t = turned.triangles[0];
    glm::dvec3 n =
        glm::cross(turned.vertices[t[1]] - turned.vertices[t[0]], turned.vertices[t[2]] - turned.vertices[t[0]]);
    EXPECT_LT(n.z, 0);
    EXPECT_NEAR(glm::length(turned.normals[t[0]]), 1.0, 1e-6);
}

TEST(Mesh, WavefrontMaterialsAreUsemtlElseGroupNames) {
    std::map<std::string, int> known{{"red", 7}, {"floor", 9}};
    auto lookup = [&](const std::string& n) { return known.count(n) ? known[n] : -1; };
    std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    Mesh m = wavefront(v + "f 1 2 3\ng floor\nf 1 2 3\nusemtl red\nf 1 2 3\nusemtl void\nf 1 2 3\n", lookup);
    EXPECT_EQ(m.materials, (std::vector<int>{-1, 9, 7, -1}));
    EXPECT_EQ(wavefront(v + "usemtl red\nf 1 2 3\n").materials, std::vector<int>{-1});  // no lookup: void
    EXPECT_EQ(wavefrontError(v + "usemtl blue\nf 1 2 3\n", lookup), "t.obj:5: undefined modifier \"blue\"");
}

TEST(Mesh, MalformedWavefrontFilesAreErrorsWithTheirLine) {
    EXPECT_EQ(wavefrontError("v 0 0 0\nv 1 0 0\nf 1 2 3\n"), "t.obj:3: bad vertex reference");
    EXPECT_EQ(wavefrontError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), "t.obj:4: bad vertex reference");
    EXPECT_EQ(wavefrontError("v 0 0\n"), "t.obj:1: bad vertex");
    EXPECT_EQ(wavefrontError("v 0 0 0\nvn 0 0 0\n"), "t.obj:2: zero normal");
    EXPECT_EQ(wavefrontError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"), "t.obj:4: too few vertices");
    EXPECT_EQ(wavefrontError("# nothing\n"), "t.obj: no faces in mesh");
}

// Every prefix of a compiled mesh is refused with a message, never read past its end.
TEST(Mesh, TruncatedRadianceMeshesAreErrors) {
    std::string bytes = fileText(kDir + "vault.rtm");
    ASSERT_GT(bytes.size(), 1000u);
    for (size_t n = 0; n < bytes.size(); n += 7) {
        Scene scene;
        std::istringstream in(bytes.substr(0, n));
        EXPECT_THROW(readRadianceMesh(scene, in, "t.rtm"), Error) << n << " bytes";
    }
    Scene scene;
    std::istringstream cut(bytes.substr(0, bytes.size() - 1));
    try {
        readRadianceMesh(scene, cut, "t.rtm");
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "t.rtm: truncated mesh");
    }
}

// Two instances of one octree and two meshes of one file load each file once; their objects follow the scene's.
TEST(Mesh, PlacedFilesLoadOncePerFile) {
    test::ScopedRayPath path(kDir.c_str());
    Scene scene = test::sceneFromText(
        "void mesh a 1 vault.rtm\n0\n0\nvoid mesh b 5 vault.rtm -t 1 0 0\n0\n0\n"
        "void instance c 1 table.oct\n0\n0\nvoid instance d 2 table.oct -mx\n0\n0\n");
    ASSERT_EQ(scene.placedFiles.size(), 2u);
    EXPECT_EQ(scene.ownObjects(), 4u);
    EXPECT_EQ(scene.placedFileOf.at(0), scene.placedFileOf.at(1));
    EXPECT_EQ(scene.placedFileOf.at(2), scene.placedFileOf.at(3));
    EXPECT_EQ(scene.objects.size(), 4u + 2u + 8u);  // the mesh's two materials, the table's eight objects
}

TEST(Mesh, MissingOrBrokenPlacedFilesAreErrorsOfTheirObject) {
    test::ScopedRayPath path(kDir.c_str());
    auto error = [](const std::string& text) {
        try {
            test::sceneFromText(text);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("void mesh m 1 nothing.rtm\n0\n0\n"), "test.rad:1: cannot find mesh file \"nothing.rtm\"");
    EXPECT_EQ(error("\nvoid instance i 1 nothing.oct\n0\n0\n"), "test.rad:2: cannot find octree file \"nothing.oct\"");
    EXPECT_EQ(error("void mesh m 1 table.oct\n0\n0\n"),
              "test.rad:1: " + kDir + "table.oct: not a mesh (FORMAT=Radiance_octree)");
    EXPECT_EQ(error("void instance i 0\n0\n0\n"),
              "test.rad:1: bad arguments for instance \"i\": expected a file name and a transform");
}

}  // namespace brume
