// The fuzzers' seed corpora run on every test: each input is read (and, for scenes, compiled for
// rendering) without crashing; rejection with a message is fine.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/exercise_cache_file.h"
#include "fuzz/exercise_cal.h"
#include "fuzz/exercise_daylight.h"
#include "fuzz/exercise_fds_input.h"
#include "fuzz/exercise_font.h"
#include "fuzz/exercise_pattern_data.h"
#include "fuzz/exercise_rays.h"
#include "fuzz/exercise_view.h"
#include "fuzz/mesh_invariants.h"
#include "world/render_scene.h"
#include "scene/mesh.h"
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

// Runs `read` on every input of a seed corpus, without warnings; rejection with a message is fine.
template <class Read>
void replay(const std::string& name, Read read) {
    auto inputs = corpus(name);
    ASSERT_FALSE(inputs.empty());
    setWarningsEnabled(false);
    for (const std::string& input : inputs) {
        std::istringstream in(input);
        try {
            read(in);
        } catch (const Error&) {
        }
    }
    setWarningsEnabled(true);
}
}  // namespace

TEST(FuzzCorpus, SceneInputsAreReadOrRefusedCleanly) {
    replay("corpus_scene", [](std::istream& in) {
        Scene scene;
        readSceneText(scene, in, "fuzz.rad", {.allowCommands = false});
        RenderScene render(scene, MaterialSettings{});
    });
}

namespace {
// A mesh read from a seed, placed twice (once mirrored) and traced through: rays across it meet it or not,
// cleanly.
void traceThrough(const Mesh& mesh) {
    Transform mirror = parseTransform(std::vector<std::string>{"-mx", "-t", "0", "0", "5"}).transform;
    SceneLayout layout;
    layout.prototypes.push_back(Prototype{0, 0, &mesh});
    for (const Transform& t : {Transform{}, mirror})
        layout.placements.push_back(Placement{0, t, t.inverse(), -1, -1, t});
    SceneGeometry geometry(std::move(layout));
    for (const dvec3& d : {dvec3(0, 0, -1), dvec3(0.3, 0.1, -1), dvec3(-1, 0.2, 0.1)}) {
        Ray ray{geometry.extent().hi + dvec3(0.5), glm::normalize(d)};
        for (int bounce = 0; bounce < 4; ++bounce) {
            auto hit = geometry.intersect(ray);
            if (!hit) break;
            ray = Ray{hit->point, ray.dir, std::numeric_limits<double>::infinity(), hit->surface};
        }
    }
}
}  // namespace

TEST(FuzzCorpus, CompiledMeshInputsAreReadOrRefusedCleanly) {
    replay("corpus_rtm", [](std::istream& in) {
        Scene scene;
        Mesh mesh = readRadianceMesh(scene, in, "fuzz.rtm");
        fuzz::checkMesh(mesh, scene.objects.size());
        traceThrough(mesh);
    });
}

TEST(FuzzCorpus, WavefrontInputsAreReadOrRefusedCleanly) {
    replay("corpus_obj", [](std::istream& in) {
        Mesh mesh = readWavefront(in, "fuzz.obj", [](const std::string& n) { return n.size() < 3 ? 0 : -1; });
        fuzz::checkMesh(mesh, 1);
        traceThrough(mesh);
    });
}

TEST(FuzzCorpus, RayInputsGiveFiniteAnswersOrAnError) {
    auto inputs = corpus("corpus_rays");
    ASSERT_FALSE(inputs.empty());
    for (const std::string& input : inputs) EXPECT_TRUE(exerciseRays(input)) << input;
}

TEST(FuzzCorpus, DataFilesAndPicturesAreReadOrRefusedCleanly) {
    for (const std::string& input : corpus("corpus_data")) EXPECT_TRUE(exerciseDataFile(input));
    for (const std::string& input : corpus("corpus_picture")) EXPECT_TRUE(exercisePicture(input));
}

TEST(FuzzCorpus, CalInputsCompileAndEvaluateCleanly) {
    setWarningsEnabled(false);
    auto inputs = corpus("corpus_cal");
    ASSERT_FALSE(inputs.empty());
    for (const std::string& text : inputs) EXPECT_TRUE(cal::exerciseCal(text)) << text;
    setWarningsEnabled(true);
}

TEST(FuzzCorpus, FontInputsAreReadOrRefusedCleanly) {
    replay("corpus_font", [](std::istream& in) {
        fuzz::exerciseFont(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
    });
}

TEST(FuzzCorpus, ViewLinesAndCameraPathsGiveFiniteRays) {
    for (const std::string& input : corpus("corpus_view")) EXPECT_TRUE(exerciseViewText(input)) << input;
}

TEST(FuzzCorpus, CacheFilesLoadOrAreRefusedCleanly) {
    setWarningsEnabled(false);  // torn blocks are dropped with a warning
    for (const std::string& input : corpus("corpus_cache")) EXPECT_TRUE(exerciseCacheFile(input));
    setWarningsEnabled(true);
    // The seeds with volume blocks are whole: the fuzzer starts from files that load volume records (a copy:
    // a cache file is opened for appending).
    fs::path seed = fs::path(BRUME_TEST_DATA) / ".." / "fuzz" / "corpus_cache" / "volume_block";
    fs::path copy = fs::temp_directory_path() / ("brume_volume_seed_" + std::to_string(getpid()));
    fs::copy_file(seed, copy, fs::copy_options::overwrite_existing);
    EXPECT_EQ(CacheFile(copy.string(), CacheIdentity{"fuzz", "fuzz", 3}).readNewVolumes().size(), 2u);
    fs::remove(copy);
}

TEST(FuzzCorpus, FdsInputsAndSignPlacementsAreReadOrRefusedCleanly) {
    replay("corpus_fds", [](std::istream& in) { fuzz::exerciseFdsInput(in); });
    replay("corpus_signs", [](std::istream& in) { fuzz::exerciseSignPlacements(in); });
}

TEST(FuzzCorpus, WeatherTapesAndMatricesAreReadOrRefusedCleanly) {
    for (const std::string& input : corpus("corpus_daylight")) EXPECT_TRUE(exerciseDaylightInput(input)) << input.substr(0, 80);
}
