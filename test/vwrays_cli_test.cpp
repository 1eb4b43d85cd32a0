// vwrays as a program: its rays against Radiance 6.1's (test/data/vwrays, made by make_reference.sh), its
// formats, jitter and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "vwrays";

// Runs vwrays with `args` (shell words, redirections allowed) in the reference data directory.
Output vwrays(const std::string& args) {
    fs::path scratch = brume_test::scratchDir("vwrays");
    return brume_test::runCaptured("cd '" + kData.string() + "' && " + BRUME_BIN_DIR + std::string("/vwrays ") + args,
                                   scratch);
}

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
}

template <typename T>
std::vector<double> binary(const std::string& bytes) {
    std::vector<T> raw(bytes.size() / sizeof(T));
    std::memcpy(raw.data(), bytes.data(), raw.size() * sizeof(T));
    return {raw.begin(), raw.end()};
}

// Both sides print six significant digits: they agree to 1e-5, relative above 1.
void expectSameRays(const std::vector<double>& got, const std::vector<double>& want, double tolerance = 1e-5) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i)
        ASSERT_NEAR(got[i], want[i], tolerance * std::max(1.0, std::abs(want[i]))) << "number " << i;
}

struct Case {
    std::string name, args;
};

std::vector<Case> cases() {
    std::ifstream in(kData / "cases.txt");
    std::vector<Case> all;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        size_t colon = line.find(": ");
        all.push_back({line.substr(0, colon), line.substr(colon + 2)});
    }
    return all;
}

}  // namespace

// Every case of cases.txt: view types, shifts, clipping, -pa, view files, pictures (any scan order), depth
// buffers, -c, -i and -d, as Radiance 6.1's vwrays gives them.
TEST(VwraysCli, RaysMatchRadiance) {
    std::vector<Case> all = cases();
    ASSERT_GE(all.size(), 25u);
    for (const Case& c : all) {
        SCOPED_TRACE(c.name + ": vwrays " + c.args);
        Output r = vwrays(c.args);
        ASSERT_EQ(r.status, 0) << r.err;
        std::string want = brume_test::slurp(kData / (c.name + ".ref"));
        if (want.rfind("-x ", 0) == 0) EXPECT_EQ(r.out, want);  // -d: the options for rtrace, exactly
        else expectSameRays(numbers(r.out), numbers(want));
    }
}

TEST(VwraysCli, BinaryFormatsCarryTheSameRays) {
    std::vector<double> want = numbers(brume_test::slurp(kData / "oblique.ref"));
    const std::string view = "-vtv -vp 1 2 3 -vd 1 -2 .5 -vu 0 0 1 -vh 60 -vv 40 -x 9 -y 7";
    Output f = vwrays("-ff " + view);
    ASSERT_EQ(f.status, 0) << f.err;
    expectSameRays(binary<float>(f.out), want);
    Output d = vwrays("-fd " + view);
    ASSERT_EQ(d.status, 0) << d.err;
    expectSameRays(binary<double>(d.out), want);
}

// -pj moves each ray within its own pixel, the same way on every run.
TEST(VwraysCli, PixelJitterStaysInPixelAndRepeats) {
    const std::string args = "-vtv -vh 90 -vv 90 -x 4 -y 4 -pj 1 -c 3";
    Output a = vwrays(args), b = vwrays(args);
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
    std::vector<double> v = numbers(a.out);
    ASSERT_EQ(v.size(), 16u * 3 * 6);
    for (size_t i = 0; i < 16 * 3; ++i) {
        const double* r = &v[6 * i];
        int pixel = int(i / 3), column = pixel % 4, row = pixel / 4;  // rows from the top
        double x = (r[3] / r[4] + 1) / 2, y = (1 - r[5] / r[4]) / 2;  // image coordinates, from the top left
        EXPECT_EQ(int(x * 4), column) << "ray " << i;
        EXPECT_EQ(int(y * 4), row) << "ray " << i;
    }
    EXPECT_NE(a.out, vwrays("-vtv -vh 90 -vv 90 -x 4 -y 4 -c 3").out);
}

// -pd: rays start on the lens (radius 0.1 about the view point) and meet the pinhole rays at the focal
// distance, the length of -vd.
TEST(VwraysCli, ApertureRaysMeetAtFocalDistance) {
    std::vector<double> lens = numbers(vwrays("-vtv -vd 0 3 0 -vh 60 -vv 60 -x 3 -y 3 -pd .2").out);
    std::vector<double> pinhole = numbers(vwrays("-vtv -vd 0 3 0 -vh 60 -vv 60 -x 3 -y 3").out);
    ASSERT_EQ(lens.size(), 54u);
    for (size_t i = 0; i < 9; ++i) {
        const double *l = &lens[6 * i], *p = &pinhole[6 * i];
        EXPECT_LE(std::hypot(l[0], l[2]), .1 + 1e-5);
        EXPECT_NEAR(l[1], 0, 1e-9);
        double tl = 3 / l[4], tp = 3 / p[4];
        EXPECT_NEAR(l[0] + tl * l[3], tp * p[3], 1e-4);
        EXPECT_NEAR(l[2] + tl * l[5], tp * p[5], 1e-4);
    }
}

// With a depth buffer, -i reports the surface point of the pixel it names. (Radiance 6.1's vwrays reads
// the depth of the pixel one up and one to the right, its loc2pix rounding a pixel centre up.)
TEST(VwraysCli, InputPixelsSeeTheirOwnDepth) {
    std::vector<double> got = numbers(vwrays("-i picture.hdr picture.zbf < pixels_small.txt").out);
    std::vector<double> all = numbers(brume_test::slurp(kData / "picture_depth.ref"));
    ASSERT_EQ(got.size(), 4u * 6);
    // pixels (0,0) (3,2) (1,1) from the bottom left are stored 8th, 3rd and 5th in "-Y 3 +X 4"
    for (auto [line, stored] : {std::pair{0, 8}, {1, 3}, {2, 5}})
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[6 * line + k], all[6 * stored + k], 1e-5);
}

TEST(VwraysCli, UnbufferedInputGivesOneRayPerLine) {
    Output r = vwrays("-i -u -x 4 -y 4 < pixels_small.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(numbers(r.out).size(), 4u * 6);
}

TEST(VwraysCli, ErrorsAreRadiances) {
    struct Bad {
        std::string args, message;
    } bad[] = {
        {"-x 0", "vwrays: bad x resolution\n"},
        {"-y -3", "vwrays: bad y resolution\n"},
        {"-vh 200", "vwrays: illegal horizontal view size\n"},
        {"-vu 0 1 0", "vwrays: view up parallel to view direction\n"},
        {"-vtq", "vwrays: unknown view type\n"},
        {"-vf nonexistent.vf", "vwrays: nonexistent.vf: cannot open\n"},
        {"-vf pixels.txt", "vwrays: pixels.txt: no view in file\n"},
        {"-q", "vwrays: unknown option -q\n"},
        {"-ft", "vwrays: bad format '-ft'\n"},
        {"", "vwrays: no view options or picture\n"},
        {"a b c", "vwrays: too many arguments\n"},
        {"cumulative.vf", "vwrays: cumulative.vf: no resolution line (not a picture)\n"},
        {"picture.hdr pixels.txt", "vwrays: pixels.txt: expected length is 12, actual length is 7\n"},
        {"-i -x 4 -y 4 < cumulative.vf", "vwrays: expected px py on input\n"},
        {"-i picture.hdr picture.zbf < pixels.txt", "vwrays: input pixel outside image\n"},
    };
    for (const Bad& b : bad) {
        SCOPED_TRACE(b.args);
        Output r = vwrays(b.args);
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.err.substr(0, b.message.size()), b.message);
    }
    EXPECT_NE(vwrays("-q").err.find("Usage: vwrays [ -i -u -f{a|f|d} -c rept | -d ]"), std::string::npos);
}
