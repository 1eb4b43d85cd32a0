#include "fds/smv_index.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <fstream>

#include "fds/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

namespace brume {
namespace {

// The shared case: eight meshes of 0.1 m cells, the soot's 3D smoke and extinction slices at 2 m (the numbers
// as the .smv prints them).
TEST(SmvIndex, ReadsTheMeshesAndOutputFilesOfARealCase) {
    std::string dir = fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    SmvIndex smv = readSmv(dir + "/model.smv");
    EXPECT_EQ(smv.chid, "model");
    ASSERT_EQ(smv.meshes.size(), 8u);
    const FdsMesh& m = smv.meshes[1];
    EXPECT_EQ(m.id, "mesh_02_01");
    EXPECT_EQ(m.cells, glm::ivec3(50, 50, 40));
    ASSERT_EQ(m.nodes[0].size(), 51u);
    EXPECT_DOUBLE_EQ(m.nodes[0].front(), 10.0);
    EXPECT_DOUBLE_EQ(m.nodes[0].back(), 15.0);
    EXPECT_DOUBLE_EQ(m.nodes[2].back(), 4.0);
    int smoke = 0, slices = 0;
    for (const FdsFile& f : smv.files) (f.kind == FdsFile::Kind::Smoke3d ? smoke : slices)++;
    EXPECT_EQ(smoke, 24);
    EXPECT_EQ(slices, 24);
    auto soot = std::find_if(smv.files.begin(), smv.files.end(),
                             [](const FdsFile& f) { return f.path.ends_with("model_2_1.s3d"); });
    ASSERT_NE(soot, smv.files.end());
    EXPECT_EQ(soot->kind, FdsFile::Kind::Smoke3d);
    EXPECT_EQ(soot->mesh, 1);
    EXPECT_EQ(soot->quantity, "SOOT DENSITY");
    EXPECT_EQ(soot->units, "kg/m3");
    EXPECT_DOUBLE_EQ(soot->massExtinction, 8700);
    auto slice = std::find_if(smv.files.begin(), smv.files.end(),
                              [](const FdsFile& f) { return f.path.ends_with("model_6_3.sf"); });
    ASSERT_NE(slice, smv.files.end());
    EXPECT_EQ(slice->mesh, 5);
    EXPECT_TRUE(slice->cellCentred);
    EXPECT_EQ(slice->quantity, "SOOT EXTINCTION COEFFICIENT");
    EXPECT_EQ(slice->range, (std::array<int, 6>{0, 50, 0, 50, 21, 21}));
    EXPECT_FALSE(slice->volume());
}

constexpr const char* kSmv = R"(CHID
 tiny

NMESHES
   1

OFFSET
      0.00000      0.00000      1.00000
GRID   only
    2    1    1    0
PDIM
 0 1 0 1 0 1 0 0 0
TRNX
    0
    0       0.00000
    1       0.50000
    2       1.00000
TRNY
    1
  stretching line
    0       0.00000
    1       1.00000
TRNZ
    0
    0       0.00000
    1       1.00000

SLCC     1 # STRUCTURED &     0     2     0     1     0     1 !      1      1
 tiny_1_1.sf
 SOOT DENSITY
 rho_soot
 kg/m3
)";

std::string written(const std::string& name, const std::string& text) {
    std::filesystem::path p = brume_test::scratchDir("smv") / name;
    std::ofstream(p) << text;
    return p.string();
}

TEST(SmvIndex, ReadsNodesWithOffsetAndSkipsStretching) {
    SmvIndex smv = readSmv(written("tiny.smv", kSmv));
    ASSERT_EQ(smv.meshes.size(), 1u);
    EXPECT_EQ(smv.meshes[0].nodes[0], (std::vector<double>{0, 0.5, 1}));
    EXPECT_EQ(smv.meshes[0].nodes[1], (std::vector<double>{0, 1}));
    EXPECT_EQ(smv.meshes[0].nodes[2], (std::vector<double>{1, 2}));
    ASSERT_EQ(smv.files.size(), 1u);
    EXPECT_TRUE(smv.files[0].volume());
    EXPECT_EQ(smv.files[0].line, 28);
}

// Each malformed index names its line and what is wrong.
TEST(SmvIndex, MalformedIndexesNameTheLine) {
    auto message = [](const std::string& text) {
        try {
            readSmv(written("bad.smv", text));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string s = kSmv;
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = s;
        return t.replace(t.find(from), from.size(), to);
    };
    EXPECT_NE(message(replaced("   1\n\nOFFSET", "   2\n\nOFFSET")).find("NMESHES says 2 but 1"), std::string::npos);
    EXPECT_NE(message(replaced("    1       0.50000", "    1       1.50000")).find("bad.smv:17: TRNX: nodes must increase"),
              std::string::npos);
    EXPECT_NE(message(replaced("SLCC     1", "SLCC     3")).find("mesh 3 does not exist"), std::string::npos);
    EXPECT_NE(message(replaced("     0     2     0     1     0     1 !", "     0     3     0     1     0     1 !"))
                  .find("bad.smv:28: slice index range outside mesh 1"),
              std::string::npos);
    EXPECT_NE(message(s.substr(0, s.find(" tiny_1_1.sf"))).find("the file ends before the file's name"),
              std::string::npos);
    EXPECT_NE(message("CHID\n x\n").find("no GRID"), std::string::npos);
    EXPECT_NE(message(replaced("    2    1    1    0", "    2    x")).find("bad.smv:10: expected 3 numbers"),
              std::string::npos);
    // A Plot3D entry: its time comes from the file's name, which must give one; its five quantities follow.
    std::string five;
    for (int q = 0; q < 5; ++q) five += " Q" + std::to_string(q) + "\n q\n u\n";
    SmvIndex index = readSmv(written("pl3d.smv", s + "PL3D        5.3     1\n tiny_1_5p03.q\n" + five));
    ASSERT_EQ(std::count_if(index.files.begin(), index.files.end(),
                            [](const FdsFile& f) { return f.kind == FdsFile::Kind::Plot3d; }),
              5);
    EXPECT_EQ(index.files.back().time, 5.03);
    EXPECT_EQ(index.files.back().block, 4);
    EXPECT_EQ(index.files.back().quantity, "Q4");
    EXPECT_NE(message(s + "PL3D        5.3     1\n tiny_1.q\n" + five).find("does not give its time"), std::string::npos);
    EXPECT_NE(message(s + "PL3D        5.3     1\n tiny_1_5p03.q\n Q0\n").find("the file ends before"), std::string::npos);
    EXPECT_THROW(readSmv("/nonexistent/case.smv"), Error);
}

}  // namespace
}  // namespace brume
