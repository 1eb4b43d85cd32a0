// The fuzzers' seed corpora run on every test: each input is read (and, for scenes, compiled for
// rendering) without crashing; rejection with a message is fine.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/exercise_cal.h"
#include "integrator/render_scene.h"
#include "io/ray_reader.h"
#include "scene/octree.h"
#include "scene/reader.h"

using namespace brume;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> corpus(const std::string& name) {
    std::vector<std::string> inputs;
    for (const auto& e : fs::directory_iterator(fs::path(BRUME_TEST_DATA) / ".." / "fuzz" / name)) {
        std::ifstream f(e.path(), std::ios::binary);
        inputs.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    return inputs;
}
}  // namespace

TEST(FuzzCorpus, SceneInputsAreReadOrRefusedCleanly) {
    setWarningsEnabled(false);
    auto inputs = corpus("corpus_scene");
    ASSERT_FALSE(inputs.empty());
    for (const std::string& text : inputs) {
        Scene scene;
        std::istringstream in(text);
        try {
            readSceneText(scene, in, "fuzz.rad", {.allowCommands = false});
            RenderScene render(scene, MaterialSettings{});
        } catch (const Error&) {
        }
    }
    setWarningsEnabled(true);
}

TEST(FuzzCorpus, RayInputsEndCleanly) {
    auto inputs = corpus("corpus_rays");
    ASSERT_FALSE(inputs.empty());
    for (const std::string& bytes : inputs) {
        std::istringstream in(bytes.substr(1));
        RayReader reader(in, "afd"[bytes[0] % 3]);
        std::array<double, 6> ray;
        int n = 0;
        while (reader.next(ray)) ++n;
        EXPECT_LE(n, int(bytes.size()));
    }
}

TEST(FuzzCorpus, CalInputsCompileAndEvaluateCleanly) {
    setWarningsEnabled(false);
    auto inputs = corpus("corpus_cal");
    ASSERT_FALSE(inputs.empty());
    for (const std::string& text : inputs) EXPECT_TRUE(cal::exerciseCal(text)) << text;
    setWarningsEnabled(true);
}
