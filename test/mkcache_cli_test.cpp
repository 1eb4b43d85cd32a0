// mkcache as a program: the records it makes are those rtrace and rpict need, and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;

using brume_test::kLampRoom;

// Sensors facing up on the floor, in rows across the room.
std::string floorGrid(int count) {
    std::string points;
    for (int i = 0; i < count; ++i)
        points += std::to_string(-4.5 + 9.0 * (i % 20) / 19) + " " + std::to_string(-4 + i / 20) + " 0 0 0 1\n";
    return points;
}

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
}

class MkcacheCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = brume_test::scratchDir("mkcache_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::ofstream(dir_ / "room.rad") << kLampRoom;
        std::ofstream(dir_ / "grid.txt") << floorGrid(60);
    }
    void TearDown() override { fs::remove_all(dir_); }
    Output run(const std::string& lines) { return brume_test::runBrume(lines, dir_); }
    fs::path dir_;
};

const std::string kOptions = " -u- -ab 2 -ad 64 -I ";

}  // namespace

// rtrace given the same points and options finds every record it needs in mkcache's file, adds none, and
// gives the values it gives without the file (the same records, made in the same order).
TEST_F(MkcacheCli, RtraceFindsEveryRecordItNeeds) {
    Output made = run("mkcache" + kOptions + "-af c room.rad < grid.txt");
    ASSERT_EQ(made.status, 0) << made.err;
    EXPECT_EQ(made.out, "");
    EXPECT_EQ(made.err.rfind("mkcache: c: ", 0), 0u) << made.err;
    EXPECT_GT(brume_test::reportedRecords(made.err), 0) << made.err;
    auto size = fs::file_size(dir_ / "c");

    Output cached = run("rtrace -h-" + kOptions + "-af c room.rad < grid.txt");
    ASSERT_EQ(cached.status, 0) << cached.err;
    EXPECT_EQ(fs::file_size(dir_ / "c"), size);
    Output fresh = run("rtrace -h-" + kOptions + "room.rad < grid.txt");
    std::vector<double> a = numbers(cached.out), b = numbers(fresh.out);
    ASSERT_EQ(a.size(), 3u * 60);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 0.1 * b[i]) << i;  // -aa .1
}

// A view's picture: rpict with the same view and options makes no record mkcache did not.
TEST_F(MkcacheCli, RpictFindsEveryRecordOfTheView) {
    std::string view = " -vp 0 0 3 -vd 0 .3 -1 -vu 0 1 0 -vh 60 -vv 60 -x 24 -y 24 -ab 1 -ad 64 -af v ";
    Output made = run("mkcache" + view + "room.rad");
    ASSERT_EQ(made.status, 0) << made.err;
    EXPECT_EQ(made.out, "");
    auto size = fs::file_size(dir_ / "v");
    Output picture = run("rpict" + view + "room.rad > v.hdr");
    ASSERT_EQ(picture.status, 0) << picture.err;
    EXPECT_EQ(fs::file_size(dir_ / "v"), size);
}

TEST_F(MkcacheCli, RefusesToRunWithoutACache) {
    Output noFile = run("mkcache -ab 2 room.rad < grid.txt");
    EXPECT_NE(noFile.status, 0);
    EXPECT_NE(noFile.err.find("-af"), std::string::npos) << noFile.err;
    for (const char* options : {"-ab 2 -aa 0", "-ab 0"}) {
        Output none = run(std::string("mkcache -af c ") + options + " room.rad < grid.txt");
        EXPECT_NE(none.status, 0) << options;
        EXPECT_NE(none.err.find("nothing to cache"), std::string::npos) << none.err;
    }
    Output noScene = run("mkcache -ab 2 -af c missing.rad < grid.txt");
    EXPECT_NE(noScene.status, 0);
    EXPECT_NE(noScene.err.find("missing.rad"), std::string::npos) << noScene.err;
    EXPECT_FALSE(fs::exists(dir_ / "c"));
}

TEST_F(MkcacheCli, HelpPrintsUsage) {
    Output help = run("mkcache -help");
    EXPECT_EQ(help.status, 0);
    EXPECT_EQ(help.out.rfind("usage: mkcache", 0), 0u) << help.out;
    EXPECT_NE(help.out.find("-af"), std::string::npos);
    Output bare = run("mkcache");
    EXPECT_NE(bare.status, 0);
    EXPECT_NE(bare.err.find("usage: mkcache"), std::string::npos) << bare.err;
}

// mkcache refuses a file made with other options, as rtrace and rpict do (rtrace_cli_test.cpp).
TEST_F(MkcacheCli, RefusesAFileOfOtherOptions) {
    ASSERT_EQ(run("mkcache" + kOptions + "-af c room.rad < grid.txt").status, 0);
    Output other = run("mkcache -u- -ab 2 -ad 128 -I -af c room.rad < grid.txt");
    EXPECT_NE(other.status, 0);
    EXPECT_NE(other.err.find("other options"), std::string::npos) << other.err;
}
