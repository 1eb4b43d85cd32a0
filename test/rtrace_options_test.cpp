// rtrace's options as Radiance pipelines pass them: -defaults reads back, options that change nothing in
// Brume are accepted and do not make a cache file "made with other options", and -al+ gives Radiance's
// bounce limit with the irradiance cache.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cli.h"
#include "scene_text.h"

namespace {

namespace fs = std::filesystem;
using brume_test::Output;

const char* kSensors = "0 0 0 0 0 1\n1 2 0 0 0 1\n-3 1 0 0 0 1\n";

class RtraceOptions : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = brume_test::scratchDir("options_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::ofstream(dir_ / "room.rad") << brume_test::kLampRoom;
        std::ofstream(dir_ / "sensors.txt") << kSensors;
    }
    void TearDown() override { fs::remove_all(dir_); }
    Output run(const std::string& lines) { return brume_test::runBrume(lines, dir_); }
    fs::path dir_;
};

}  // namespace

// `rtrace -defaults > f; rtrace @f scene` runs with the defaults: every line reads back (an option with no
// value unless given, -T, is a comment), and the values are those of no options at all.
TEST_F(RtraceOptions, DefaultsReadBack) {
    ASSERT_EQ(run("rtrace -defaults > defaults.opt").status, 0);
    Output withFile = run("rtrace @defaults.opt -h- -I -u- -ab 1 room.rad < sensors.txt");
    ASSERT_EQ(withFile.status, 0) << withFile.err;
    Output plain = run("rtrace -h- -I -u- -ab 1 room.rad < sensors.txt");
    EXPECT_EQ(withFile.out, plain.out);
    EXPECT_EQ(std::count(withFile.out.begin(), withFile.out.end(), '\n'), 3);
    for (const char* name : {"mkcache", "rpict"}) {
        Output d = run(std::string(name) + " -defaults > " + name + ".opt && " + name + " @" + name +
                       ".opt -defaults > again.opt && cmp " + name + ".opt again.opt");
        EXPECT_EQ(d.status, 0) << name << ": " << d.err;
    }
}

// -am, -as, -aw, -dc, -dj, -dp and -ss, which Radiance pipelines pass, change nothing in Brume: accepted,
// the same values, and a cache file made without them is not "made with other options"; an option that
// does change values still makes it refused.
TEST_F(RtraceOptions, OptionsThatChangeNothingKeepACacheFile) {
    const std::string base = "rtrace -h- -I -u- -ab 2 -ad 64 ";
    Output made = run(base + "-af c.af room.rad < sensors.txt");
    ASSERT_EQ(made.status, 0) << made.err;
    Output same = run(base + "-am 0 -as 1024 -aw 3 -dc .5 -dj .7 -dp 64 -ss 0 -af c.af room.rad < sensors.txt");
    EXPECT_EQ(same.status, 0) << same.err;
    EXPECT_EQ(same.out, made.out);
    Output other = run(base + "-ar 32 -af c.af room.rad < sensors.txt");
    EXPECT_NE(other.status, 0);
    EXPECT_NE(other.err.find("other options: -ar"), std::string::npos) << other.err;
    Output help = run("rtrace -help");
    for (const char* o : {"-am", "-as", "-aw", "-dc", "-dj", "-dp", "-ss"}) {
        size_t at = help.out.find(std::string("  ") + o + " ");
        ASSERT_NE(at, std::string::npos) << o;
        EXPECT_NE(help.out.substr(at, help.out.find('\n', at) - at).find("changes nothing"), std::string::npos) << o;
    }
}

// -ab says what it does: with the cache the bounces past it go on by Russian roulette, -al+ stops them.
// In an integrating sphere (ρ .5, a small lamp at its centre) -ab 2 with the cache gives every bounce,
// E₀/(1 − ρ), and with -al+ what Radiance's cache gives, E₀(1 + ρ + ρ²); tolerance 2% (-aa .1 records
// over six sensors, as CachedIrradiance's sphere tests).
TEST(AmbientLimit, StopsTheCacheAtAbBouncesAsRadiance) {
    using namespace brume;
    test::TestScene t("void plastic wall 0 0 5 .5 .5 .5 0 0\nwall bubble inside 0 0 4 0 0 0 1\n"
                      "void light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4 0 0 0 0.02\n");
    const double direct = 0.02 * 0.02 * std::numbers::pi * 1000;  // Φ/(4πR²)
    auto measure = [&](bool limit) {
        RenderSettings s = test::fixedSeed();
        s.ambientBounces = 2;
        s.ambientLimit = limit;
        Sequence sequence(t.scene, t.render, s);
        const dvec3 dirs[] = {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-0.6, 0.8, 0}, {0, -0.6, 0.8}, {0.48, 0.6, -0.64}};
        std::vector<double> v(6);
        sequence.run(6, 0, [&](size_t i, WorkItem& item) {
            v[i] = sequence.integrator().irradiance({dirs[i] * (1 - 1e-4), -dirs[i], i}, item).value[0];
        });
        return (v[0] + v[1] + v[2] + v[3] + v[4] + v[5]) / 6;
    };
    EXPECT_NEAR(measure(false), 2 * direct, 0.02 * 2 * direct);
    EXPECT_NEAR(measure(true), 1.75 * direct, 0.02 * 1.75 * direct);
}
