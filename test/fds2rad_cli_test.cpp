// fds2rad end to end: the shared FDS case's building as a scene rays cross as the case's geometry says (its doors
// open, its walls closed), signs placed by position whose luminance and front are right, and vismap's sign list
// beside; bad input named, nothing written.
#include <gtest/gtest.h>

#include <sstream>

#include "cli.h"
#include "fds/testing.h"
#include "scratch_dir.h"

namespace {

using brume_test::Output;

std::vector<double> numbers(const std::string& line) {
    std::istringstream in(line);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
}

TEST(Fds2rad, TheSharedCasesBuildingWithSignsPlaced) {
    const std::string dir = brume::fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    auto scratch = brume_test::scratchDir("fds2rad");
    std::ofstream(scratch / "placed.txt") << "# name  centre  front  width height  kind  L|rho\n"
                                             "north_exit 17.47 10 2.35  0 -1 0  0.4 0.2 emitting 150\n"
                                             "door_exit 10 3.87 2.35    1 0 0   0.4 0.2 emitting 150\n"
                                             "plan 12.5 0 1.5           0 1 0   0.4 0.3 reflecting 0.8\n"
                                             "in_wall 5 4.65 1.5        0 1 0   0.4 0.3 reflecting 0.8\n";
    Output r = brume_test::runBrume("fds2rad -s placed.txt -S signs.txt '" + dir + "/model.fds' > building.rad", scratch);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "fds2rad: warning - placed.txt:5: sign 'in_wall' faces into a solid (1 cm before it is an obstruction)\n");
    EXPECT_EQ(brume_test::slurp(scratch / "signs.txt"),
              "# polygon kind C (fds2rad -s)\nnorth_exit emitting 8\ndoor_exit emitting 8\nplan reflecting 3\nin_wall reflecting 3\n");
    // From the hall at eye height: the north exit sign straight ahead shows its 150 cd/m²; the door to the rooms is
    // open (a ray through it goes on along the corridor between the rooms to the domain's wall at x = 0); the north
    // door is open (nothing there: Radiance's "infinite" distance); the south wall is closed.
    Output trace = brume_test::runBrume(
        "printf '17.47 5 2.35 0 1 0\\n12 3.87 1 -1 0 0\\n17.47 5 1 0 1 0\\n15 5 1.7 0 -1 0\\n' | "
        "rtrace -h -ab 0 -ovL building.rad",
        scratch);
    ASSERT_EQ(trace.status, 0) << trace.err;
    std::istringstream rows(trace.out);
    std::vector<std::vector<double>> v;
    for (std::string line; std::getline(rows, line);) v.push_back(numbers(line));
    ASSERT_EQ(v.size(), 4u);
    const double luminance = 179 * (0.265 * v[0][0] + 0.670 * v[0][1] + 0.065 * v[0][2]);
    EXPECT_NEAR(luminance, 150, 0.5);
    EXPECT_NEAR(v[0][3], 4.995, 1e-6);  // the sign, 5 mm before the wall at y = 10
    EXPECT_NEAR(v[1][3], 12, 1e-6);
    EXPECT_GE(v[2][3], 1e10);
    EXPECT_NEAR(v[3][3], 5, 1e-6);
    // vismap reads the scene and the list as they are.
    Output study = brume_test::runBrume("printf 'hall 15 5 1.7\\n' > route.txt && "
                                        "vismap -S signs.txt -wp route.txt -ab 0 -vr 2 building.rad", scratch);
    ASSERT_EQ(study.status, 0) << study.err;
    EXPECT_NE(study.out.find(",north_exit,emitting,"), std::string::npos) << study.out;
}

TEST(Fds2rad, BadInputIsNamedAndWritesNothing) {
    auto scratch = brume_test::scratchDir("fds2rad_bad");
    std::ofstream(scratch / "open.fds") << "&MESH XB=0,1,0,1,0,1 /\n&OBST XB=0,1,0,1,0,1\n";
    Output r = brume_test::runBrume("fds2rad open.fds", scratch);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "fds2rad: open.fds:2: &OBST is not closed by '/'\n");
    std::ofstream(scratch / "case.fds") << "&MESH XB=0,1,0,1,0,1 /\n";
    std::ofstream(scratch / "bad_signs.txt") << "exit 0.5 0.5 0.5 0 0 0 0.4 0.2 emitting 150\n";
    r = brume_test::runBrume("fds2rad -s bad_signs.txt -S list.txt case.fds", scratch);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "fds2rad: bad_signs.txt:1: sign 'exit': its front has no direction\n");
    EXPECT_FALSE(std::filesystem::exists(scratch / "list.txt"));
    std::ofstream(scratch / "materials.txt") << "wall 0.5\nfloor 0.2 0.3\n";
    r = brume_test::runBrume("fds2rad -m materials.txt case.fds", scratch);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "fds2rad: materials.txt:2: expected 'SURF_ID r g b' or 'SURF_ID rho'\n");
    std::ofstream(scratch / "materials.txt") << "wall 1.5\n";
    r = brume_test::runBrume("fds2rad -m materials.txt case.fds", scratch);
    EXPECT_EQ(r.err, "fds2rad: materials.txt:1: a reflectance is between 0 and 1\n");
    EXPECT_EQ(r.out, "");
    r = brume_test::runBrume("fds2rad -S list.txt case.fds", scratch);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("-S: the sign list comes from signs given by -s"), std::string::npos) << r.err;
}

}  // namespace
