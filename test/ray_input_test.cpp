// Rays on the standard input of rtrace and mkcache, in every format: rows that are not six finite numbers
// are errors naming their line or record, after the rays before them are answered; valid input, pipes from
// vwrays and Radiance-style grid files go through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "cli.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;

const char* kScene =
    "void light lum 0 0 3 100 100 100\n"
    "lum sphere bulb 0 0 4 0 0 2 0.1\n"
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";

const std::string kRow = "0 0 1 0 0 -1\n";

template <typename T>
std::string records(std::initializer_list<T> values) {
    std::string bytes(values.size() * sizeof(T), '\0');
    std::memcpy(bytes.data(), std::data(values), bytes.size());
    return bytes;
}

const std::string kFloatRay = records<float>({0, 0, 1, 0, 0, -1});
const std::string kDoubleRay = records<double>({0, 0, 1, 0, 0, -1});

std::string repeat(const std::string& s, int n) {
    std::string all;
    for (int i = 0; i < n; ++i) all += s;
    return all;
}

// One malformed input: its format letter, its bytes, what the reader says and how many rays come before it.
struct BadInput {
    char format;
    std::string bytes, message;
    int answered;
};

std::vector<BadInput> badInputs() {
    const float fnan = std::numeric_limits<float>::quiet_NaN(), finf = std::numeric_limits<float>::infinity();
    const char* notANumber = " is not a number (a ray is six numbers: origin and direction)";
    const char* commas = " is not a number: fields are separated by white space, not commas";
    return {
        {'a', kRow + kRow + "0 0 1 x 0 -1\n" + kRow, "(stdin):3: \"x\"" + std::string(notANumber), 2},
        {'a', "x y z dx dy dz\n" + kRow + kRow, "(stdin):1: \"x\"" + std::string(notANumber), 0},
        {'a', "x,y,z,dx,dy,dz\n0,0,1,0,0,-1\n", "(stdin):1: \"x,y,z,dx,dy,dz\"" + std::string(commas), 0},
        {'a', kRow + "0, 0, 1, 0, 0, -1\n", "(stdin):2: \"0,\"" + std::string(commas), 1},
        {'a', repeat(kRow, 4) + "0 0 1 0 0\n" + kRow, "(stdin):5: 5 numbers, a ray needs 6", 4},
        {'a', repeat(kRow, 6) + "0 0 1 0 0 -1 1\n" + kRow, "(stdin):7: 7 numbers, a ray needs 6", 6},
        {'a', kRow + kRow + "0 0 1 nan 0 -1\n" + kRow, "(stdin):3: \"nan\" is not a finite number", 2},
        {'a', kRow + "inf 0 1 0 0 -1\n", "(stdin):2: \"inf\" is not a finite number", 1},
        {'a', kRow + "\n\n1e999 0 1 0 0 -1\n", "(stdin):4: \"1e999\" is not a finite number", 1},
        {'f', kFloatRay + kFloatRay + kFloatRay.substr(0, 20), "(stdin): ray 3: partial record, 20 of 24 bytes", 2},
        {'f', kFloatRay + records<float>({0, 0, 1, fnan, 0, -1}) + kFloatRay,
         "(stdin): ray 2: number 4 of 6 is NaN, not a finite number", 1},
        {'f', records<float>({finf, 0, 1, 0, 0, -1}), "(stdin): ray 1: number 1 of 6 is infinite, not a finite number", 0},
        {'d', repeat(kDoubleRay, 3) + kDoubleRay.substr(0, 40), "(stdin): ray 4: partial record, 40 of 48 bytes", 3},
        {'d', kDoubleRay + records<double>({0, 0, 1, 0, 0, std::nan("")}) + kDoubleRay,
         "(stdin): ray 2: number 6 of 6 is NaN, not a finite number", 1},
    };
}

class RayInput : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = brume_test::scratchDir("ray_input");
        std::ofstream(dir_ / "s.rad") << kScene;
    }
    // Runs the shell command `line`, a pipeline perhaps (Brume's programs first on the PATH), with `input` on
    // its standard input.
    Output run(const std::string& line, const std::string& input) {
        std::ofstream(dir_ / "in", std::ios::binary) << input;
        return brume_test::runBrume("{ " + line + "; } < in", dir_);
    }
    fs::path dir_;
};

long lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

}  // namespace

// Each malformed input in each format, plainly, for sensors (-I) and at hits (-i): the message names the line
// or record, the status is 1, and exactly the rays before it are answered.
TEST_F(RayInput, BadRowsAreErrorsAfterTheRaysBeforeThemAreAnswered) {
    for (const BadInput& bad : badInputs())
        for (const char* mode : {"", "-I ", "-i "}) {
            Output r = run(std::string("rtrace -h- -ov ") + mode + "-f" + bad.format + "a s.rad", bad.bytes);
            SCOPED_TRACE(std::string(mode) + bad.message);
            EXPECT_EQ(r.status, 1);
            EXPECT_EQ(r.err, "rtrace: " + bad.message + "\n");
            EXPECT_EQ(lines(r.out), bad.answered) << r.out;
        }
}

// Binary output too holds the records of the rays before the bad one, whole; a flush interval (-x) or a flush
// request splits them into batches, all answered.
TEST_F(RayInput, BinaryOutputAndSmallBatchesHoldEveryRayBeforeTheBadOne) {
    std::string rays = repeat(kFloatRay, 5) + kFloatRay.substr(0, 7);
    Output f = run("rtrace -h- -ov -fff s.rad", rays);
    EXPECT_EQ(f.status, 1);
    EXPECT_EQ(f.err, "rtrace: (stdin): ray 6: partial record, 7 of 24 bytes\n");
    EXPECT_EQ(f.out.size(), 5 * 3 * sizeof(float));
    Output x = run("rtrace -h- -ov -x 2 s.rad", repeat(kRow, 5) + "0 0 1 0 0\n");
    EXPECT_EQ(x.status, 1);
    EXPECT_EQ(lines(x.out), 5);
    Output flushed = run("rtrace -h- -ov s.rad", kRow + "0 0 0 0 0 0\n" + kRow + kRow + "end\n");
    EXPECT_EQ(flushed.status, 1);
    EXPECT_EQ(flushed.err, "rtrace: (stdin):5: \"end\" is not a number (a ray is six numbers: origin and direction)\n");
    EXPECT_EQ(lines(flushed.out), 4);
}

// -x and -y stop reading at their count: what follows is not read, good or bad.
TEST_F(RayInput, ResolutionLimitStopsBeforeABadRow) {
    Output r = run("rtrace -h- -ov -x 2 -y 1 s.rad", kRow + kRow + "x y z\n");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lines(r.out), 3);  // the resolution line and two rays
}

TEST_F(RayInput, BlankLinesAndFlushRaysAreValidInput) {
    Output r = run("rtrace -h- -ov s.rad", "\n" + kRow + "\n  \t\n0 0 0 0 0 0\n0 0 1 0 0 -1\r\n\n" + kRow.substr(0, 12));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(lines(r.out), 4);
}

// A Radiance-style sensor grid: tabs, %g numbers, signs and exponents, no newline after the last row.
TEST_F(RayInput, RadianceGridFilesAreRead) {
    Output r = run("rtrace -h- -I -ab 1 -ad 32 -aa 0 s.rad",
                   "-4.5\t-4.5\t0.8\t0\t0\t1\n-1.5e+00 4.5 8e-1 -0 0 1\n+2.25 .5 0.80 0. 0 1.");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lines(r.out), 3);
}

// vwrays' rays through a pipe, in each format, answered one per pixel (its view fits 64 by 46 pixels); a
// pipe cut short ends in a partial record, after the rays before it.
TEST_F(RayInput, VwraysPipesAreAnswered) {
    const std::string view = " -x 64 -y 48 -vp 0 0 3 -vd 0 0 -1 -vu 0 1 0 -vh 60 -vv 45 ";
    for (const char* f : {"a", "f", "d"}) {
        Output r = run(std::string("vwrays -f") + f + view + "| rtrace -h- -ov -f" + f + "a $(vwrays -d" + view +
                           ") s.rad",
                       "");
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "") << f;
        EXPECT_EQ(r.out.rfind("-Y       46 +X       64\n", 0), 0u) << f;
        EXPECT_EQ(lines(r.out), 1 + 64 * 46) << f;
    }
    Output cut = run("vwrays -ff" + view + "| head -c 1000 | rtrace -h- -ov -ffa s.rad", "");
    EXPECT_EQ(cut.status, 1);
    EXPECT_EQ(cut.err, "rtrace: (stdin): ray 42: partial record, 16 of 24 bytes\n");
    EXPECT_EQ(lines(cut.out), 41);
}

// mkcache reads as rtrace does: the same messages under its own name, the points before the bad one cached.
TEST_F(RayInput, MkcacheCachesThePointsBeforeABadOne) {
    std::string grid;
    for (int i = 0; i < 40; ++i) grid += std::to_string(-4 + 0.2 * i) + " 0.5 0 0 0 1\n";
    const std::string options = "mkcache -u- -I -ab 1 -ad 32 -aa .2 ";
    Output bad = run(options + "-af bad s.rad", grid + "0 0 0 0 0 1 # sensor 41\n" + kRow);
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.err, "mkcache: (stdin):41: \"#\" is not a number (a ray is six numbers: origin and direction)\n");
    Output good = run(options + "-af good.amb s.rad", grid);
    ASSERT_EQ(good.status, 0) << good.err;
    EXPECT_GT(fs::file_size(dir_ / "good.amb"), 0u);
    EXPECT_EQ(fs::file_size(dir_ / "bad"), fs::file_size(dir_ / "good.amb"));
    for (const BadInput& b : badInputs()) {
        Output r = run(std::string("mkcache -ab 1 -ad 8 -af c") + b.format + " -f" + b.format + " s.rad", b.bytes);
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.err, "mkcache: " + b.message + "\n");
    }
}
