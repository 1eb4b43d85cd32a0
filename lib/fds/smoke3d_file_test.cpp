#include "fds/smoke3d_file.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fds/slice_file.h"
#include "fds/smv_index.h"
#include "fds/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

namespace brume {
namespace {

using fds_test::writeRecord;

// A 3D smoke file of a 1 x 1 x 1 mesh (8 nodes): per frame a time, the sizes and the run-length code.
std::string smoke3d(const std::string& name, const std::vector<std::pair<float, std::vector<std::uint8_t>>>& frames,
                    std::vector<std::int32_t> header = {1, 0, 0, 1, 0, 1, 0, 1}, std::streamoff cut = 0) {
    std::filesystem::path p = brume_test::scratchDir("s3d") / name;
    {
        std::ofstream out(p, std::ios::binary);
        writeRecord(out, header);
        for (const auto& [time, code] : frames) {
            writeRecord(out, std::vector<float>{time});
            writeRecord(out, std::vector<std::int32_t>{8, std::int32_t(code.size())});
            writeRecord(out, code);
        }
    }
    if (cut) std::filesystem::resize_file(p, std::filesystem::file_size(p) - std::uint64_t(cut));
    return p.string();
}

// Literals, and 255 v n for n copies of v (Smokeview's code): exact.
TEST(Smoke3dFile, DecodesRunsAndLiterals) {
    Smoke3dFile f = readSmoke3d(smoke3d("runs.s3d", {{0.5f, {7, 255, 3, 5, 9, 9}}, {1.5f, {255, 0, 8}}}), glm::ivec3(1));
    ASSERT_EQ(f.frames.size(), 2u);
    EXPECT_FALSE(f.truncated);
    EXPECT_EQ(f.frames[0].time, 0.5);
    EXPECT_EQ(f.frames[0].bytes, (std::vector<std::uint8_t>{7, 3, 3, 3, 3, 3, 9, 9}));
    EXPECT_EQ(f.frames[1].bytes, std::vector<std::uint8_t>(8, 0));
}

// A file FDS is still writing ends inside a frame: the whole frames before it are kept.
TEST(Smoke3dFile, KeepsTheWholeFramesOfATruncatedFile) {
    for (std::streamoff cut : {1, 5, 10, 14, 20}) {
        Smoke3dFile f =
            readSmoke3d(smoke3d("cut.s3d", {{0.5f, {255, 1, 8}}, {1.5f, {255, 2, 8}}}, {1, 0, 0, 1, 0, 1, 0, 1}, cut), glm::ivec3(1));
        EXPECT_TRUE(f.truncated) << cut;
        ASSERT_EQ(f.frames.size(), 1u) << cut;
        EXPECT_EQ(f.frames[0].bytes[0], 1);
    }
}

TEST(Smoke3dFile, RefusesWhatItCannotDecode) {
    auto message = [](const std::string& path) {
        try {
            readSmoke3d(path, glm::ivec3(1));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(smoke3d("short.s3d", {{0.5f, {1, 2, 3}}})).find("short.s3d: frame 1 (byte "), std::string::npos);
    EXPECT_NE(message(smoke3d("long.s3d", {{0.5f, {255, 1, 9}}})).find("does not give one byte per node"),
              std::string::npos);
    EXPECT_NE(message(smoke3d("escape.s3d", {{0.5f, {1, 1, 1, 1, 1, 1, 1, 255, 1}}})).find("run-length"),
              std::string::npos);
    EXPECT_NE(message(smoke3d("times.s3d", {{1.5f, {255, 1, 8}}, {0.5f, {255, 1, 8}}})).find("frame 2 (byte 79): times"),
              std::string::npos);
    EXPECT_NE(message(smoke3d("mesh.s3d", {}, {1, 0, 0, 2, 0, 1, 0, 1})).find("not that of a 3D smoke file of 1 x 1 x 1"),
              std::string::npos);
    EXPECT_NE(message(smoke3d("nan.s3d", {{NAN, {255, 1, 8}}})).find("times"), std::string::npos);
    std::filesystem::path text = brume_test::scratchDir("s3d") / "text.s3d";
    std::ofstream(text) << "not a Fortran file at all, but some text\n";
    EXPECT_NE(message(text.string()).find("text.s3d: byte 0: the header is cut short, or this is not FDS output"), std::string::npos);
}

// FDS encodes b = 254 (1 − exp(−K_m ρ Δx)), rounded: decoding inverts it.
TEST(Smoke3dFile, SootBytesInvertFdsEncoding) {
    for (double rho : {1e-6, 3e-5, 2e-4, 1e-3}) {
        double b = 254 * (1 - std::exp(-8700 * rho * 0.1));
        EXPECT_NEAR(sootDensity(b, 8700, 0.1), rho, 1e-12 + 1e-9 * rho);
    }
    EXPECT_EQ(sootDensity(0, 8700, 0.1), 0);
    EXPECT_TRUE(std::isfinite(sootDensity(254, 8700, 0.1)));
}

// The import checked against FDS itself (../shared/data, FDS 6.7.9): K_m times the soot density of mesh 2's
// 3D smoke against FDS's own cell-centred slice of the soot extinction coefficient in the cells at z 2.0–2.1 m,
// at all 151 instants. The 3D smoke holds nodes, each the mean of its 8 cells, so a cell's value here is the
// mean of its 8 nodes; each byte is ±0.5 of a step, about ±0.02 /m at these 0.1 m cells. Measured: the slice
// within the bytes' interval in 99.4 % of the interior cells (not next to the mesh's sides, whose nodes
// average in ghost and wall cells), mean relative difference −0.1 % where the slice exceeds 0.05 /m (rounding,
// not truncation, which would give +10 %). Tolerance: 98 % and ±1 %.
TEST(Smoke3dFile, SootMatchesFdsExtinctionSliceWithinItsBytes) {
    std::string dir = fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    SmvIndex smv = readSmv(dir + "/model.smv");
    const FdsMesh& mesh = smv.meshes[1];
    Smoke3dFile smoke = readSmoke3d(dir + "/model_2_1.s3d", mesh.cells);
    SliceFile slice = readSlice(dir + "/model_2_3.sf");
    ASSERT_EQ(smoke.frames.size(), 151u);
    ASSERT_EQ(slice.frames.size(), 151u);
    const double km = 8700, dx = mesh.nodes[0][1] - mesh.nodes[0][0];
    const int nx = mesh.cells.x + 1, ny = mesh.cells.y + 1, k = slice.range[4];  // the slice's cells: k = 21
    size_t inside = 0, cells = 0, compared = 0;
    double relative = 0;
    for (size_t f = 0; f < 151; ++f) {
        ASSERT_EQ(smoke.frames[f].time, slice.frames[f].time);
        for (int j = 2; j <= 49; ++j)
            for (int i = 2; i <= 49; ++i) {
                double lo = 0, mid = 0, hi = 0;
                for (int c = 0; c < 8; ++c) {
                    double b = smoke.frames[f].bytes[size_t((i - 1 + c % 2) + nx * (j - 1 + c / 2 % 2 + ny * (k - 1 + c / 4)))];
                    lo += km * sootDensity(std::max(0.0, b - 0.5), km, dx) / 8;
                    mid += km * sootDensity(b, km, dx) / 8;
                    hi += km * sootDensity(b + 0.5, km, dx) / 8;
                }
                double s = slice.frames[f].values[size_t(i + 51 * j)];
                ++cells;
                inside += s >= lo - 1e-6 && s <= hi + 1e-6;
                if (s > 0.05) ++compared, relative += (mid - s) / s;
            }
    }
    relative /= double(compared);
    std::printf("slice within the bytes' interval: %.2f %% of %zu; mean relative difference %.3f %%\n",
                100.0 * double(inside) / double(cells), cells, 100 * relative);
    EXPECT_GT(double(inside) / double(cells), 0.98);
    EXPECT_LT(std::abs(relative), 0.01);
}

}  // namespace
}  // namespace brume
