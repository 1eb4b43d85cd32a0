#include "scene/octree_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/octree.h"
#include "scene/reader.h"
#include "same_objects.h"
#include "scoped_directory.h"

using namespace brume;

namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "scene";

// Runs a test in the directory of the scene files: normal octrees name them relative to it.
class InDataDirectory : public ::testing::Test {
    brume_test::ScopedDirectory here_{kData};
};

Scene textScene() {
    Scene scene;
    readSceneFile(scene, "scene.rad");
    return scene;
}

std::string bytesOf(const OctreeContents& octree) {
    std::ostringstream out;
    writeOctree(out, octree);
    return out.str();
}

Scene readBack(const std::string& bytes) {
    std::istringstream in(bytes);
    Scene scene;
    readOctree(scene, in, "t.oct");
    return scene;
}

// A tree node over leaves listing some objects, an empty one and a single one.
std::vector<OctreeNode> someNodes() {
    std::vector<OctreeNode> nodes{{true, {}}};
    for (int i = 0; i < 8; ++i) nodes.push_back({false, i == 3 ? std::vector<int>{} : std::vector<int>{4, 8, i + 9}});
    return nodes;
}

TEST_F(InDataDirectory, AFrozenOctreeHoldsTheObjectsOfItsText) {
    Scene text = textScene();
    OctreeCube cube{{-0.5, 1e-3, 2}, 4.25};
    std::string bytes = bytesOf({{"#?RADIANCE", "oconv -f scene.rad", "NOTE= kept"}, cube, {}, &text, text.objects.size(), someNodes()});
    Scene scene = readBack(bytes);
    brume_test::expectSameObjects(scene, text);
    EXPECT_EQ(scene.headerLines, (std::vector<std::string>{"#?RADIANCE", "oconv -f scene.rad", "NOTE= kept"}));
    ASSERT_TRUE(scene.cube);
    EXPECT_EQ(scene.cube->origin, cube.origin);
    EXPECT_EQ(scene.cube->size, cube.size);
}

// Radiance's oconv made scene.oct from scene.rad (test/data/scene/README.md): all up to the nodes is laid out
// byte for byte as it is there (header, magic, cube, file names, object count).
TEST_F(InDataDirectory, ANormalOctreeIsLaidOutAsRadiancesOconvLaysItOut) {
    std::ifstream in("scene.oct", std::ios::binary);
    std::string radiance(std::istreambuf_iterator<char>(in), {});
    Scene text = textScene();
    Scene fromRadiance = readBack(radiance);
    std::string bytes = bytesOf({{"#?RADIANCE", "oconv scene.rad"}, *fromRadiance.cube, {"scene.rad"}, &text, text.objects.size(), someNodes()});
    size_t nodes = radiance.find(std::string("scene.rad\0\0", 11)) + 11 + 4;
    ASSERT_LT(nodes, radiance.size());
    EXPECT_EQ(bytes.substr(0, nodes), radiance.substr(0, nodes));
    EXPECT_EQ(readBack(bytes).objects.size(), text.objects.size());  // the listed file read again
}

TEST(OctreeWriter, RealsAreRadiancesPortableReals) {
    Scene scene;
    std::istringstream in("void plastic p 0 0 5 0.1 -2.5 1e30 1e-300 -1e-7\n");
    readSceneText(scene, in, "t.rad");
    std::string bytes = bytesOf({{"#?RADIANCE"}, {}, {}, &scene, 1, {{}}});
    std::vector<double> reals = readBack(bytes).objects[0].reals;
    ASSERT_EQ(reals.size(), 5u);
    EXPECT_NEAR(reals[0], 0.1, 0.1 * 1e-9);
    EXPECT_NEAR(reals[1], -2.5, 2.5 * 1e-9);
    EXPECT_NEAR(reals[2], 1e30, 1e30 * 1e-9);
    EXPECT_EQ(reals[3], 0);  // below 2^-128, Radiance's format holds no more than 0
    EXPECT_NEAR(reals[4], -1e-7, 1e-7 * 1e-9);
}

TEST(OctreeWriter, ObjectsWithIntegerArgumentsCannotBeFrozen) {
    Scene scene;
    std::istringstream in("void plastic p 0 2 1 2 5 .5 .5 .5 0 0\n");
    readSceneText(scene, in, "t.rad");
    try {
        bytesOf({{"#?RADIANCE"}, {}, {}, &scene, 1, {{}}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "t.rad:1: cannot freeze plastic \"p\": it has integer arguments");
    }
}

}  // namespace
