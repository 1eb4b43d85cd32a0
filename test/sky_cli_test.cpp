// gensky and gendaylit as programs: their scene text against Radiance 6.1's for the command lines of
// test/data/sky/commands.txt (references written by test/data/sky/make_radiance_outputs.sh), and their
// errors.
#include <gtest/gtest.h>


#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "same_words.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;
using brume_test::slurp;

// Runs a command line ("gensky 3 21 12 ...") with Brume's programs first on PATH, so that the program
// sees its plain name as argv[0], as it does when a scene says `!gensky ...`.
Output run(const std::string& commandLine) {
    return brume_test::runCaptured("PATH=" + std::string(BRUME_BIN_DIR) + ":$PATH " + commandLine,
                                   brume_test::scratchDir("sky"));
}

}  // namespace

// Every command line of commands.txt, from sunny, intermediate, overcast and uniform skies with time
// zones, solar time, -y, -B/-R and the 87° limit, to gendaylit's -W/-P/-L/-G/-E inputs, -O units, -C
// colour, -i intervals and its error skies: Brume's output is Radiance's to the printed precision (on
// this machine it is byte for byte the same for all of them; the test allows one unit of the last digit
// so that another libm's rounding does not fail it).
TEST(SkyCli, OutputMatchesRadianceToPrintedPrecision) {
    // Brume's programs must be there: otherwise PATH would find another gensky, Radiance's perhaps.
    for (const char* program : {"gensky", "gendaylit"}) ASSERT_TRUE(fs::exists(fs::path(BRUME_BIN_DIR) / program)) << program;
    std::ifstream commands(std::string(BRUME_TEST_DATA) + "/sky/commands.txt");
    std::string line;
    int n = 0;
    while (std::getline(commands, line)) {
        char name[16];
        std::snprintf(name, sizeof name, "%02d.txt", ++n);
        Output brume = run(line);
        ASSERT_EQ(brume.status, 0) << line << "\n" << brume.err;
        std::string radiance = slurp(fs::path(BRUME_TEST_DATA) / "sky" / "radiance" / name);
        ASSERT_FALSE(radiance.empty()) << name;
        brume_test::expectSameWords(brume.out, radiance, line);
    }
    EXPECT_GE(n, 16);
}

TEST(SkyCli, UsageErrorsNameTheProblemAndShowTheUsage) {
    struct Case {
        const char* command;
        const char* message;
    };
    for (Case c : {Case{"gensky 13 1 12", "gensky: bad month"}, Case{"gensky 3 32 12", "gensky: bad day"},
                   Case{"gensky 3 21", "gensky: arg count"}, Case{"gensky 3 21 12 -q", "gensky: unknown option -q"},
                   Case{"gensky 3 21 12 sunny", "gensky: bad option sunny"},
                   Case{"gensky 3 21 12XYZ", "gensky: unknown time zone: XYZ"},
                   Case{"gensky 3 21 +12EST", "gensky: bad time format: +12EST"},
                   Case{"gensky 3 21 12 -a", "gensky: missing argument for option -a"},
                   Case{"gendaylit 3 21 24 -W 500 100", "gendaylit: bad hour"},
                   Case{"gendaylit 3 21 12 -W 500", "gendaylit: missing argument for option -W"},
                   Case{"gendaylit -ang 30 0 -W 500 100 -O 3", "gendaylit: bad output specification"},
                   Case{"gendaylit -ang 30 0 -W 500 100 -i -60", "gendaylit: time interval negative"}}) {
        Output r = run(c.command);
        EXPECT_EQ(r.status, 1) << c.command;
        EXPECT_TRUE(r.out.empty()) << c.command;
        EXPECT_EQ(r.err.rfind(c.message, 0), 0u) << c.command << "\n" << r.err;
        EXPECT_NE(r.err.find("usage: "), std::string::npos) << c.command;
    }
}

// Where Brume differs on purpose: gendaylit reads times as gensky does, so 12:30 is half past twelve
// (Radiance's gendaylit reads it as 12) and a time zone sets the meridian.
TEST(SkyCli, GendaylitReadsMinutesAndTimeZones) {
    std::string minutes = run("gendaylit 3 21 12:30 -a 45 -o 0 -m 0 -W 600 150").out;
    std::string decimal = run("gendaylit 3 21 12.5 -a 45 -o 0 -m 0 -W 600 150").out;
    EXPECT_EQ(minutes.substr(minutes.find('\n')), decimal.substr(decimal.find('\n')));
    std::string zone = run("gendaylit 3 21 13.5CET -a 45 -o 0 -W 600 150").out;
    EXPECT_EQ(zone.substr(zone.find('\n')), decimal.substr(decimal.find('\n')));
}
