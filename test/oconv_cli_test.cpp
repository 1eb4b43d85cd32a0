// oconv as a program: the octrees it writes give rtrace the scene Radiance's octrees give it, its refusals.
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

const fs::path kData = fs::path(BRUME_TEST_DATA);

const char* const kRays = "2 2 .5 0 0 1\n1 3 .5 .3 -.2 -1\n3 1 .2 -1 0 0\n2 2 1.5 0 0 -1\n.2 3.8 1 1 -1 .1\n";

fs::path sceneCase(const std::string& name) {
    fs::path dir = brume_test::scratchDir("oconv_" + name);
    fs::copy_file(kData / "scene/room.rad", dir / "room.rad", fs::copy_options::overwrite_existing);
    fs::copy_file(kData / "scene/room_frozen.oct", dir / "radiance.oct", fs::copy_options::overwrite_existing);
    std::ofstream(dir / "rays.txt") << kRays;
    return dir;
}

const char* const kTrace = "rtrace -h -u- -ab 2 -ad 128 -ov ";

// Radiance's oconv -f made radiance.oct from room.rad (test/data/scene/README.md). Brume's frozen octree
// holds the same objects (reals rounded alike) in the same cube, so rtrace gives the same bytes from both;
// a normal octree lists room.rad, read again.
TEST(OconvCli, RtraceGivesTheSameValuesFromBrumesOctreeAsFromRadiances) {
    fs::path dir = sceneCase("same");
    Output o = brume_test::runBrume("oconv -f room.rad > frozen.oct && oconv room.rad > normal.oct && for o in radiance frozen normal; do " +
                                        std::string(kTrace) + "$o.oct < rays.txt > $o.txt || exit; done",
                                    dir);
    ASSERT_EQ(o.status, 0) << o.err;
    std::string radiance = brume_test::slurp(dir / "radiance.txt");
    EXPECT_EQ(std::count(radiance.begin(), radiance.end(), '\n'), 5);
    EXPECT_NE(radiance.find_first_of("123456789"), std::string::npos);  // lit
    EXPECT_EQ(brume_test::slurp(dir / "frozen.txt"), radiance);
    // The normal octree's reals are the text's, not rounded to 31 bits: the same values to a few units of
    // the sixth digit.
    std::istringstream normal(brume_test::slurp(dir / "normal.txt")), expected(radiance);
    size_t values = 0;
    for (double a, e; expected >> e && normal >> a; ++values) EXPECT_NEAR(a, e, 1e-6 * std::abs(e));
    EXPECT_EQ(values, 15u);
    EXPECT_NE(brume_test::slurp(dir / "normal.oct").find(std::string("room.rad\0\0", 10)), std::string::npos);
}

TEST(OconvCli, TheStandardInputMakesAFrozenOctree) {
    fs::path dir = sceneCase("stdin");
    Output o = brume_test::runBrume("oconv - < room.rad > in.oct && " + std::string(kTrace) + "in.oct < rays.txt > in.txt && " +
                                        kTrace + "radiance.oct < rays.txt > radiance.txt",
                                    dir);
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(brume_test::slurp(dir / "in.txt"), brume_test::slurp(dir / "radiance.txt"));
}

// -i adds to an octree as Radiance's oconv does: its cube kept, its header copied before the new command line,
// its files listed first (a frozen one makes a frozen one, with a warning). The new objects lie inside the room,
// so the octree of all the files at once has the same cube, and rtrace the same bytes through both.
TEST(OconvCli, AddingToAnOctreeGivesTheOctreeOfAllItsFiles) {
    fs::path dir = sceneCase("add");
    std::ofstream(dir / "more.rad") << "grey sphere more 0 0 4 3 2 .3 .25\nlum sphere lamp2 0 0 4 1 1 2.5 .1\n";
    Output o = brume_test::runBrume("oconv room.rad > base.oct && oconv -i base.oct more.rad > added.oct && "
                                    "oconv room.rad more.rad > all.oct && oconv -i radiance.oct more.rad > frozen_added.oct && "
                                    "oconv -f room.rad more.rad > frozen_all.oct && for o in added all frozen_added frozen_all; do " +
                                        std::string(kTrace) + "$o.oct < rays.txt > $o.txt || exit; done",
                                    dir);
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(o.err, "oconv: warning - radiance.oct: frozen octree: so is the new one\n");
    EXPECT_EQ(brume_test::slurp(dir / "added.txt"), brume_test::slurp(dir / "all.txt"));
    EXPECT_EQ(brume_test::slurp(dir / "frozen_added.txt"), brume_test::slurp(dir / "frozen_all.txt"));
    EXPECT_NE(brume_test::slurp(dir / "added.txt").find_first_of("123456789"), std::string::npos);  // lit
    std::string added = brume_test::slurp(dir / "added.oct");
    EXPECT_NE(added.find("\noconv room.rad\n"), std::string::npos);
    EXPECT_NE(added.find(" -i base.oct more.rad\nFORMAT=Radiance_octree\n"), std::string::npos);
    EXPECT_NE(added.find(std::string("room.rad\0more.rad\0\0", 19)), std::string::npos);
    EXPECT_EQ(brume_test::slurp(dir / "frozen_added.oct").find(std::string("room.rad\0", 9)), std::string::npos);
}

// Errors name the program, the file and line; nothing reaches the standard output.
TEST(OconvCli, BadInputIsRefusedWithNothingWritten) {
    fs::path dir = sceneCase("errors");
    std::ofstream(dir / "bad.rad") << "void plastic m 0 0 5 .5 .5 .5 0 0\nm sphere s 0 0 3 1 2 3\n";
    std::ofstream(dir / "ball.rad") << "void plastic m 0 0 5 .5 .5 .5 0 0\nm sphere s 0 0 4 1 2 3 .5\n";
    std::ofstream(dir / "far.rad") << "grey sphere far 0 0 4 9 9 9 .5\n";
    struct Case {
        std::string line, error;
    } cases[] = {
        {"oconv -x room.rad", "oconv: unknown option: '-x'\nusage: oconv"},
        {"oconv", "oconv: no scene files\nusage: oconv"},
        {"oconv -r 0 room.rad", "oconv: -r needs a positive integer"},
        {"oconv -n", "oconv: missing value for -n"},
        {"oconv -r x room.rad", "oconv: bad value for -r: 'x'"},
        {"oconv -i", "oconv: missing value for -i"},
        {"oconv -b 0 0 0 -1 room.rad", "oconv: -b needs a positive size"},
        {"oconv -i old.oct room.rad", "oconv: old.oct: cannot open octree file"},
        {"oconv -b 0 0 0 4 -i radiance.oct ball.rad", "oconv: only one of '-b' or '-i'"},
        {"oconv -f -i radiance.oct far.rad", "oconv: far.rad:1: boundary does not encompass scene (sphere \"far\" is outside it)"},
        {"oconv missing.rad", "oconv: missing.rad: cannot"},
        {"oconv room.rad bad.rad", "oconv: bad.rad:2: bad arguments for sphere \"s\""},
        {"oconv - < bad.rad", "oconv: standard input:2: bad arguments for sphere \"s\""},
        {"oconv -b 0 0 0 3 ball.rad", "oconv: ball.rad:2: boundary does not encompass scene (sphere \"s\" is outside it)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.line);
        Output o = brume_test::runBrume(c.line, dir);
        EXPECT_EQ(o.status, 1);
        EXPECT_EQ(o.out, "");
        EXPECT_EQ(o.err.rfind(c.error, 0), 0u) << o.err;
    }
    Output fits = brume_test::runBrume("oconv -b 0 0 0 4 ball.rad", dir);
    EXPECT_EQ(fits.status, 0) << fits.err;
    EXPECT_NE(fits.out.find(std::string("-1e-05\0-1e-05\0-1e-05\0004.00002\0", 29)), std::string::npos);  // -b less and plus OMARGIN
}

// More than 511 objects meeting everywhere in one cube (Radiance's limit on a leaf's list): the first 511 are
// listed, and a warning names the first left out, unless -w.
TEST(OconvCli, ALeafOverRadiancesLimitIsWarnedOf) {
    fs::path dir = sceneCase("overflow");
    std::ofstream pile(dir / "pile.rad");
    pile << "void plastic m 0 0 5 .5 .5 .5 0 0\n";
    for (int i = 0; i < 520; ++i) pile << "m polygon p" << i << " 0 0 9 0 0 0 1 0 0 0 1 0\n";
    pile.close();
    Output warned = brume_test::runBrume("oconv pile.rad > pile.oct", dir);
    EXPECT_EQ(warned.status, 0);
    EXPECT_NE(warned.err.find("oconv: warning - set overflow: more than 511 objects meet one cube that is divided no further "
                              "(first left out: polygon \"p511\")"),
              std::string::npos) << warned.err;
    Output quiet = brume_test::runBrume("oconv -w pile.rad > pile.oct", dir);
    EXPECT_EQ(quiet.status, 0);
    EXPECT_EQ(quiet.err, "");
}

}  // namespace
