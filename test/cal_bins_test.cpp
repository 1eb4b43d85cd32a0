// The sky's patches as bins: Brume's tregenza.cal, reinhart.cal and reinhartb.cal against Radiance 6.1's
// rcalc with its own files (test/data/daymtx/bins.txt, made by make_bins.sh beside it), and SkyPatches'
// patchAt (gendaymtx's rows) against the files.
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <sstream>

#include "cal/embedded.h"
#include "cal/testing.h"
#include "sky/sky_patches.h"

namespace {

using brume::cal::testing::Calc;

std::string calFile(const std::string& name) {
    for (const brume::EmbeddedFile& f : brume::cal::embeddedCalFiles())
        if (f.name == name) return std::string(f.text);
    ADD_FAILURE() << "no " << name;
    return {};
}

// A file loaded as rcalc -f loads it, into the global context, with `before` and `after` definitions.
double bin(const std::string& before, const std::string& file, const std::string& after, const char* variable,
           const double d[3]) {
    Calc calc;
    if (!before.empty()) calc.library.loadText(before, "before.cal");
    calc.library.loadText(calFile(file), file);
    if (!after.empty()) calc.library.loadText(after, "after.cal");
    for (int k = 0; k < 3; ++k) calc.channels[1 + k] = d[k];
    return calc(variable);
}

// Each line of a file of Radiance's bins: a direction, then `n` bins; the number of lines.
template <size_t n, class F>
int forEachDirection(const std::string& file, F check) {
    std::ifstream in(std::string(BRUME_TEST_DATA) + file);
    int lines = 0;
    for (std::string line; std::getline(in, line); ++lines) {
        std::istringstream words(line);
        double d[3];
        std::array<double, n> expected;
        for (double& v : d) words >> v;
        for (double& v : expected) words >> v;
        check(d, expected, line);
    }
    return lines;
}

}  // namespace

TEST(CalBins, SkyPatchBinsAreRadiances) {
    brume::SkyPatches m1(1), m2(2), m4(4);
    int n = forEachDirection<6>("/daymtx/bins.txt", [&](const double* d, const auto& expected, const std::string& line) {
        EXPECT_EQ(bin("", "tregenza.cal", "", "tbin", d), expected[0]) << line;
        EXPECT_EQ(bin("MF:1;", "reinhart.cal", "", "rbin", d), expected[1]) << line;
        EXPECT_EQ(bin("MF:2;", "reinhart.cal", "", "rbin", d), expected[2]) << line;
        EXPECT_EQ(bin("MF:4;", "reinhart.cal", "", "rbin", d), expected[3]) << line;
        EXPECT_EQ(bin("", "reinhartb.cal", "MF=2;RHS=-1;rNx=0;rNy=1;rNz=0;Ux=0;Uy=0;Uz=1;", "rbin", d), expected[4]) << line;
        EXPECT_EQ(bin("", "reinhartb.cal", "MF=1;JTR=1;", "rbin", d), expected[5]) << line;
        glm::dvec3 dir(d[0], d[1], d[2]);
        EXPECT_EQ(m1.patchAt(dir), expected[1]) << line;
        EXPECT_EQ(m2.patchAt(dir), expected[2]) << line;
        EXPECT_EQ(m4.patchAt(dir), expected[3]) << line;
    });
    EXPECT_EQ(n, 400);
    EXPECT_EQ(bin("MF:2;", "reinhart.cal", "", "Nrbins", std::array<double, 3>{0, 0, 1}.data()), 578);
    EXPECT_EQ(bin("", "reinhartb.cal", "MF=4;", "Nrbins", std::array<double, 3>{0, 0, 1}.data()), 2305);
}

// The Klems bases' patches as bins: Brume's klems_full.cal, klems_half.cal and klems_quarter.cal against Radiance
// 6.1's rcalc with its own files (test/data/rfluxmtx/klems_bins.txt, made by make_klems_bins.sh beside it), in
// frames of either hand, with an up that is not unit, and jittered.
TEST(CalBins, KlemsBinsAreRadiances) {
    int n = forEachDirection<7>("/rfluxmtx/klems_bins.txt", [&](const double* d, const auto& expected, const std::string& line) {
        EXPECT_EQ(bin("", "klems_full.cal", "RHS=1;", "kbinS", d), expected[0]) << line;
        EXPECT_EQ(bin("", "klems_full.cal", "RHS=-1;", "kbin(0.36,-0.8,0.48,0.1,0.2,1.7)", d), expected[1]) << line;
        EXPECT_EQ(bin("", "klems_full.cal", "JTR=1;", "kbin(0,0,-1,0,1,0)", d), expected[2]) << line;
        EXPECT_EQ(bin("", "klems_half.cal", "RHS=1;", "khbin(-0.6,0,-0.8,0,0,2)", d), expected[3]) << line;
        EXPECT_EQ(bin("", "klems_half.cal", "RHS=-1;", "khbin(0,0,-1,0,1,0)", d), expected[4]) << line;
        EXPECT_EQ(bin("", "klems_quarter.cal", "RHS=1;", "kqbin(0.36,-0.8,0.48,0.1,0.2,1.7)", d), expected[5]) << line;
        EXPECT_EQ(bin("", "klems_quarter.cal", "JTR=.5;", "kqbin(1,0,0,0,0,1)", d), expected[6]) << line;
    });
    EXPECT_EQ(n, 400);
    const double up[3] = {0, 0, 1};
    EXPECT_EQ(bin("", "klems_full.cal", "", "Nkbins", up), 145);
    EXPECT_EQ(bin("", "klems_half.cal", "", "Nkhbins", up), 77);
    EXPECT_EQ(bin("", "klems_quarter.cal", "", "Nkqbins", up), 41);
}
