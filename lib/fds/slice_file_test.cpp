#include "fds/slice_file.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fds/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

namespace brume {
namespace {

using fds_test::writeRecord;

std::vector<char> label(const std::string& s) {
    std::string padded = s + std::string(30 - s.size(), ' ');
    return {padded.begin(), padded.end()};
}

// A cell-centred slice over 2 x 1 x 1 values: header, then per frame a time and the values.
std::string slice(const std::string& name, const std::vector<std::pair<float, std::vector<float>>>& frames,
                  std::streamoff cut = 0) {
    std::filesystem::path p = brume_test::scratchDir("sf") / name;
    {
        std::ofstream out(p, std::ios::binary);
        writeRecord(out, label("SOOT DENSITY"));
        writeRecord(out, label("rho_soot"));
        writeRecord(out, label("kg/m3"));
        writeRecord(out, std::vector<std::int32_t>{0, 1, 3, 3, 5, 5});
        for (const auto& [time, values] : frames) {
            writeRecord(out, std::vector<float>{time});
            writeRecord(out, values);
        }
    }
    if (cut) std::filesystem::resize_file(p, std::filesystem::file_size(p) - std::uint64_t(cut));
    return p.string();
}

TEST(SliceFile, ReadsLabelsRangeAndFrames) {
    SliceFile f = readSlice(slice("ok.sf", {{0, {1, 2}}, {2.5f, {3, 4}}}));
    EXPECT_EQ(f.quantity, "SOOT DENSITY");
    EXPECT_EQ(f.units, "kg/m3");
    EXPECT_EQ(f.range, (std::array<int, 6>{0, 1, 3, 3, 5, 5}));
    ASSERT_EQ(f.frames.size(), 2u);
    EXPECT_EQ(f.frames[1].time, 2.5);
    EXPECT_EQ(f.frames[1].values, (std::vector<float>{3, 4}));
    EXPECT_FALSE(f.truncated);
    for (std::streamoff cut : {1, 12, 13}) {
        SliceFile t = readSlice(slice("cut.sf", {{0, {1, 2}}, {2.5f, {3, 4}}}, cut));
        EXPECT_TRUE(t.truncated);
        EXPECT_EQ(t.frames.size(), 1u);
    }
}

TEST(SliceFile, RefusesWrongSizesAndValuesThatAreNotNumbers) {
    auto message = [](const std::string& path) {
        try {
            readSlice(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(slice("three.sf", {{0, {1, 2, 3}}})).find("three.sf: frame 1 (byte 158): holds 3 values, not 2"),
              std::string::npos);
    EXPECT_NE(message(slice("inf.sf", {{0, {1, INFINITY}}})).find("not a number"), std::string::npos);
    EXPECT_NE(message(slice("back.sf", {{1, {1, 2}}, {1, {1, 2}}})).find("frame 2"), std::string::npos);
}

// The shared case's cell-centred slices hold a ghost cell at index 0 of each direction: at the side two meshes
// share, mesh 4's ghost row (j = 0) is mesh 2's last row of cells (j = 50), at every instant, exactly.
TEST(SliceFile, NeighbouringMeshesShareTheirSideCells) {
    std::string dir = fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    SliceFile south = readSlice(dir + "/model_2_3.sf"), north = readSlice(dir + "/model_4_3.sf");
    EXPECT_EQ(south.quantity, "SOOT EXTINCTION COEFFICIENT");
    EXPECT_EQ(south.units, "1/m");
    ASSERT_EQ(south.frames.size(), 151u);
    ASSERT_EQ(north.frames.size(), 151u);
    EXPECT_EQ(south.frames.back().time, 180.0);
    double largest = 0;
    for (size_t f = 0; f < 151; ++f)
        for (int i = 1; i <= 50; ++i) {
            ASSERT_EQ(north.frames[f].values[size_t(i)], south.frames[f].values[size_t(i + 51 * 50)]) << f << " " << i;
            largest = std::max(largest, double(north.frames[f].values[size_t(i)]));
        }
    EXPECT_GT(largest, 0.1);  // not a comparison of empty air
}

}  // namespace
}  // namespace brume
