#include "fds/smoke3d16_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "fds/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

namespace brume {
namespace {

using fds_test::writeRecord;

struct Frame {
    float time, lo, hi;
    std::vector<std::uint16_t> steps;  // per node
    std::int32_t count = 8;
};

// A 16-bit smoke file of a 1 x 1 x 1 mesh (8 nodes): per frame a time, the counts and range, the big-endian steps.
std::string smoke16(const std::string& name, const std::vector<Frame>& frames,
                    std::vector<std::int32_t> header = {1, 1, 0, 2, 2, 2}, std::streamoff cut = 0) {
    std::filesystem::path p = brume_test::scratchDir("s16") / name;
    {
        std::ofstream out(p, std::ios::binary);
        writeRecord(out, header);
        for (const Frame& f : frames) {
            writeRecord(out, std::vector<float>{f.time});
            std::int32_t sizes[4] = {f.count, f.count};
            std::memcpy(&sizes[2], &f.lo, 4), std::memcpy(&sizes[3], &f.hi, 4);
            writeRecord(out, std::vector<std::int32_t>(sizes, sizes + 4));
            std::vector<std::uint8_t> bytes;
            for (std::uint16_t s : f.steps) bytes.push_back(std::uint8_t(s >> 8)), bytes.push_back(std::uint8_t(s & 255));
            writeRecord(out, bytes);
        }
    }
    if (cut) std::filesystem::resize_file(p, std::filesystem::file_size(p) - std::uint64_t(cut));
    return p.string();
}

// value = lo + (hi − lo) u / 65535, u big-endian: exact at the ends and in between.
TEST(Smoke3d16File, DecodesStepsOverEachFramesRange) {
    std::vector<std::uint16_t> steps = {0, 65535, 32768, 1, 256, 255, 65534, 0};
    Smoke3d16File f = readSmoke3d16(
        smoke16("steps.s16", {{0.5f, 20, 1020, steps}, {1.5f, 3, 4, steps}}, {1, 1, 0, 2, 2, 2}, 5), glm::ivec3(1));
    ASSERT_EQ(f.frames.size(), 1u);  // the second frame cut short, as a file FDS is still writing
    EXPECT_TRUE(f.truncated);
    EXPECT_EQ(f.frames[0].time, 0.5);
    for (size_t n = 0; n < 8; ++n) EXPECT_FLOAT_EQ(f.frames[0].values[n], float(20 + 1000.0 * steps[n] / 65535)) << n;
}

TEST(Smoke3d16File, RefusesWhatItCannotDecode) {
    auto message = [](const std::string& path) {
        try {
            readSmoke3d16(path, glm::ivec3(1));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::vector<std::uint16_t> eight(8, 7);
    EXPECT_NE(message(smoke16("mesh.s16", {}, {1, 1, 0, 3, 2, 2})).find("not that of an uncompressed 16-bit smoke file"),
              std::string::npos);
    EXPECT_NE(message(smoke16("packed.s16", {}, {1, 1, 1, 2, 2, 2})).find("uncompressed"), std::string::npos);
    EXPECT_NE(message(smoke16("count.s16", {{0.5f, 0, 1, eight, 9}})).find("frame 1 (byte "), std::string::npos);
    EXPECT_NE(message(smoke16("short.s16", {{0.5f, 0, 1, {1, 2, 3}}})).find("two bytes per node"), std::string::npos);
    EXPECT_NE(message(smoke16("nan.s16", {{0.5f, NAN, 1, eight}})).find("not finite"), std::string::npos);
    EXPECT_NE(message(smoke16("inverted.s16", {{0.5f, 2, 1, eight}})).find("not finite"), std::string::npos);
    EXPECT_NE(message(smoke16("times.s16", {{1.5f, 0, 1, eight}, {0.5f, 0, 1, eight}})).find("times"), std::string::npos);
}

TEST(Smoke3d16File, IsFoundBesideItsSmokeFile) {
    const std::string dir = std::string(BRUME_TEST_DATA) + "/fds/slices_s16/";
    EXPECT_EQ(smoke3d16Beside(dir + "slices_s16_1_1.s3d"), dir + "slices_s16_1_1.s16");
    EXPECT_EQ(smoke3d16Beside(fds_test::twoMeshCase() + "/two_mesh_smoke_1_1.s3d"), "");
    EXPECT_EQ(smoke3d16Beside(dir + "slices_s16_1_1.sf"), "");
}

}  // namespace
}  // namespace brume
