#include "scene/octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/reader.h"
#include "same_objects.h"
#include "scoped_directory.h"
#include "scratch_dir.h"

namespace brume {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(BRUME_TEST_DATA) + "/scene";

using brume_test::ScopedDirectory;

Scene readText() {
    Scene scene;
    readSceneFile(scene, kData + "/scene.rad");
    return scene;
}

std::string octreeError(const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        Scene scene;
        readOctree(scene, in, "t.oct");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Octree, FrozenOctreeGivesTheSameObjectsAsItsText) {
    Scene scene;
    readOctreeFile(scene, kData + "/scene_frozen.oct");
    brume_test::expectSameObjects(scene, readText());
    EXPECT_EQ(scene.sources, (std::vector<std::string>{kData + "/scene_frozen.oct"}));
}

TEST(Octree, FrozenOctreeHoldsNoAliases) {
    Scene scene;
    readOctreeFile(scene, kData + "/scene_frozen.oct");
    for (const SceneObject& object : scene.objects) EXPECT_NE(object.type, "alias");
    const SceneObject& bare = scene.objects.at(scene.findModifier("bare"));
    EXPECT_EQ(bare.type, "plastic");
    EXPECT_EQ(bare.modifier, -1);
}

TEST(Octree, FrozenModifierIndicesFollowRadiancesIdenticalRedefinitionRule) {
    Scene scene;
    readOctreeFile(scene, kData + "/scene_frozen.oct");
    const SceneObject& s4 = scene.objects.back();
    ASSERT_EQ(s4.name, "s4");
    EXPECT_EQ(s4.modifier, 1);  // the first "shiny", as oconv recorded it
}

TEST(Octree, NormalOctreeRereadsItsSceneFilesFromTheCurrentDirectory) {
    ScopedDirectory dir(kData);
    Scene scene;
    readOctreeFile(scene, "scene.oct");
    brume_test::expectSameObjects(scene, readText());
    EXPECT_EQ(scene.objects[0].where.str(), "scene.rad:3");
    EXPECT_EQ(scene.sources, (std::vector<std::string>{"scene.oct", "scene.rad"}));
}

TEST(Octree, MissingSceneFileIsAnErrorNamingTheOctree) {
    ScopedDirectory dir(kData + "/lib");
    Scene scene;
    try {
        readOctreeFile(scene, "../scene.oct");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "../scene.oct: scene.rad: cannot find scene file");
    }
}

TEST(Octree, StaleOctreeIsAnError) {
    fs::path dir = brume_test::scratchDir("stale_octree");
    fs::copy_file(kData + "/scene.oct", dir / "scene.oct", fs::copy_options::overwrite_existing);
    std::ofstream(dir / "scene.rad") << fileBytes(kData + "/scene.rad") << "void plastic extra 0 0 0\n";
    ScopedDirectory cd(dir);
    Scene scene;
    EXPECT_THROW(
        {
            try {
                readOctreeFile(scene, "scene.oct");
            } catch (const Error& e) {
                EXPECT_STREQ(e.what(), "scene.oct: bad object count; octree stale?");
                throw;
            }
        },
        Error);
}

TEST(Octree, HeaderLinesAreKeptWithoutTheFormat) {
    Scene scene;
    readOctreeFile(scene, kData + "/scene_frozen.oct");
    EXPECT_EQ(scene.headerLines, (std::vector<std::string>{"#?RADIANCE", "oconv -f scene.rad"}));
}

TEST(Octree, BoundingCubeIsRead) {
    Scene scene;
    readOctreeFile(scene, kData + "/scene_frozen.oct");
    ASSERT_TRUE(scene.cube);
    EXPECT_EQ(scene.cube->origin, (std::array<double, 3>{-0.10001, -0.05001, -0.45001}));
    EXPECT_EQ(scene.cube->size, 4.10002);
}

TEST(Octree, OctreesAreToldApartFromText) {
    std::ifstream octree(kData + "/scene.oct", std::ios::binary), text(kData + "/scene.rad");
    EXPECT_TRUE(isOctree(octree));
    EXPECT_EQ(octree.tellg(), 0);
    EXPECT_FALSE(isOctree(text));
    std::istringstream picture("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n");
    EXPECT_FALSE(isOctree(picture));
    std::istringstream comment("#?RADIANCE header copied as a comment\nvoid plastic a 0 0 0\n");
    EXPECT_FALSE(isOctree(comment));
}

TEST(Octree, LoadSceneReadsASingleOctree) {
    Scene scene = loadScene({kData + "/scene_frozen.oct"});
    EXPECT_EQ(scene.objects.size(), readText().objects.size());
    EXPECT_TRUE(scene.cube);
}

TEST(Octree, SceneFilesMayFollowAnOctreeOnlyOne) {
    Scene scene = loadScene({kData + "/scene_frozen.oct", kData + "/lib/found.rad"});
    EXPECT_GT(scene.objects.size(), readText().objects.size());
    EXPECT_TRUE(scene.cube);
    for (const std::vector<std::string>& paths :
         {std::vector<std::string>{kData + "/lib/found.rad", kData + "/scene_frozen.oct"},
          {kData + "/scene_frozen.oct", kData + "/scene_frozen.oct"}}) {
        try {
            loadScene(paths);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()),
                      kData + "/scene_frozen.oct: an octree must be the first scene argument, and the only octree");
        }
    }
}

TEST(Octree, TruncatedOctreeIsAnError) {
    std::string bytes = fileBytes(kData + "/scene_frozen.oct");
    for (size_t size : {bytes.size() - 1, bytes.size() / 2, size_t(60), size_t(30)})
        EXPECT_EQ(octreeError(bytes.substr(0, size)), size == 30 ? "t.oct: not an octree (no information header)"
                                                                 : "t.oct: truncated octree");
}

TEST(Octree, DamagedOctreesAreErrors) {
    std::string bytes = fileBytes(kData + "/scene_frozen.oct");
    size_t binary = bytes.find("\n\n") + 2;
    std::string badMagic = bytes;
    badMagic[binary + 1] = 0x1b;  // 283 + objsize 0
    EXPECT_EQ(octreeError(badMagic), "t.oct: incompatible octree format");
    std::string badFormat = "#?RADIANCE\nFORMAT=ascii\n\n";
    EXPECT_EQ(octreeError(badFormat), "t.oct: not an octree (FORMAT=ascii)");
    std::string badNode = bytes;
    badNode[bytes.find('\0', bytes.find("4.10002")) + 6] = 7;  // the root node's kind
    EXPECT_EQ(octreeError(badNode), "t.oct: damaged octree");
}

}  // namespace
}  // namespace brume
