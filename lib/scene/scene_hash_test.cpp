#include "scene/scene_hash.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene_text.h"

namespace brume {
namespace {

namespace fs = std::filesystem;
using test::sceneFromText;

std::string hashOf(const std::string& text) { return sceneContentHash(sceneFromText(text)); }

const std::string kRoom = "void plastic white 0 0 5 .7 .7 .7 0 0\n"
                          "white sphere ball 0 0 4 1 2 3 0.5\n";

TEST(SceneHash, IgnoresWhitespaceCommentsAndWhereTheSceneWasRead) {
    Scene other;
    std::istringstream in("# the same room, laid out differently\n"
                          "void   plastic white\n0\n0\n5 .7 .7 .7 0 0\n\n"
                          "white sphere ball 0 0 4 1 2 3 .5  # a ball\n");
    readSceneText(other, in, "elsewhere.rad");
    EXPECT_EQ(hashOf(kRoom), sceneContentHash(other));
    EXPECT_EQ(hashOf(kRoom).size(), 32u);
}

TEST(SceneHash, ChangesWithAnyArgumentTypeNameOrModifier) {
    std::string room = hashOf(kRoom);
    EXPECT_NE(room, hashOf("void plastic white 0 0 5 .7 .7 .6 0 0\nwhite sphere ball 0 0 4 1 2 3 0.5\n"));
    EXPECT_NE(room, hashOf("void metal white 0 0 5 .7 .7 .7 0 0\nwhite sphere ball 0 0 4 1 2 3 0.5\n"));
    EXPECT_NE(room, hashOf("void plastic white 0 0 5 .7 .7 .7 0 0\nwhite sphere orb 0 0 4 1 2 3 0.5\n"));
    EXPECT_NE(room, hashOf("void plastic white 0 0 5 .7 .7 .7 0 0\nvoid sphere ball 0 0 4 1 2 3 0.5\n"));
    EXPECT_NE(hashOf("void brightfunc f 2 a b.cal 0 0\n"), hashOf("void brightfunc f 2 a c.cal 0 0\n"));
    EXPECT_NE(hashOf("void brightfunc f 2 a b.cal 0 1 2\n"), hashOf("void brightfunc f 2 a b.cal 0 1 3\n"));
}

// A directory on RAYPATH holding the files a scene names.
class RayPathFiles {
public:
    RayPathFiles()
        : dir_(fs::temp_directory_path() / ("brume_scene_hash_" + std::to_string(getpid()))), path_(dir_.c_str()) {}
    ~RayPathFiles() { fs::remove_all(dir_); }
    void write(const std::string& name, const std::string& content) const {
        fs::create_directories(dir_);
        std::ofstream(dir_ / name) << content;
    }

private:
    fs::path dir_;
    test::ScopedRayPath path_;
};

TEST(SceneHash, ChangesWithTheContentOfTheFilesTheSceneReads) {
    RayPathFiles files;
    files.write("hash_light.dat", "1\n0 90 3\n1 2 3\n");
    files.write("hash_light.cal", "corr(v) = v;\n");
    const std::string scene = "void brightdata light 4 corr hash_light.dat hash_light.cal Acos(Dz)/DEGREE 0 0\n";
    std::string original = hashOf(scene);

    files.write("hash_light.dat", "1\n0 90 3\n1 2 4\n");
    EXPECT_NE(hashOf(scene), original);
    files.write("hash_light.dat", "1\n0 90 3\n1 2 3\n");
    EXPECT_EQ(hashOf(scene), original) << "the same content again, rewritten later";
    files.write("hash_light.cal", "corr(v) = 2 * v;\n");
    EXPECT_NE(hashOf(scene), original);
}

}  // namespace
}  // namespace brume
