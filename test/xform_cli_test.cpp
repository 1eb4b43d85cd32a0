// xform as a program: its output compared with Radiance 6.1's for the command lines of
// data/xform/cases.txt (expected outputs made by data/xform/regenerate.sh), its errors, and Brume's
// xform found by "!xform" lines of scenes read by rtrace.
#include <gtest/gtest.h>


#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "xform";

using brume_test::Output;
using brume_test::slurp;

// Runs a shell command line in data/xform, with Brume's programs first on PATH and RAYPATH=.
Output run(const std::string& command, const fs::path& dir = kData) {
    return brume_test::runCaptured("cd '" + dir.string() + "' && PATH='" + BRUME_BIN_DIR + "':\"$PATH\" RAYPATH=. sh -c '" +
                                       command + "' < /dev/null",
                                   brume_test::scratchDir("xform"));
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    return parts;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string word; in >> word;) w.push_back(word);
    return w;
}

bool isNumber(const std::string& word, double& value) {
    char* end;
    value = std::strtod(word.c_str(), &end);
    return !word.empty() && *end == '\0';
}

// Numbers agree to the 12 significant digits xform prints (1e-11 relative), or within 1e-12 near zero:
// Radiance is built with -mfma, whose rounding leaves noise such as 4.7e-16 where Brume computes 6.2e-16.
bool sameNumber(double a, double b) {
    return std::abs(a - b) <= 1e-11 * std::max(std::abs(a), std::abs(b)) + 1e-12;
}

// The first line where Brume's output differs from Radiance's beyond that, or "".
std::string firstDifference(const std::string& brume, const std::string& radiance) {
    std::vector<std::string> b = split(brume, '\n'), r = split(radiance, '\n');
    for (size_t i = 0; i < std::max(b.size(), r.size()); ++i) {
        std::string bl = i < b.size() ? b[i] : "<end>", rl = i < r.size() ? r[i] : "<end>";
        std::vector<std::string> bw = words(bl), rw = words(rl);
        bool same = bw.size() == rw.size();
        for (size_t k = 0; same && k < bw.size(); ++k) {
            double x, y;
            same = bw[k] == rw[k] || (isNumber(bw[k], x) && isNumber(rw[k], y) && sameNumber(x, y));
        }
        if (!same) return "line " + std::to_string(i + 1) + ": Brume '" + bl + "', Radiance '" + rl + "'";
    }
    return "";
}

TEST(XformCli, OutputMatchesRadianceForEveryCase) {
    int cases = 0;
    for (const std::string& line : split(slurp(kData / "cases.txt"), '\n')) {
        if (line.empty() || line[0] == '#') continue;
        auto tab = line.find('\t');
        std::string name = line.substr(0, tab), command = line.substr(tab + 1);
        SCOPED_TRACE(name + ": " + command);
        Output o = run(command);
        EXPECT_EQ(o.status, 0) << o.err;
        EXPECT_EQ(firstDifference(o.out, slurp(kData / "expected" / (name + ".txt"))), "");
        ++cases;
    }
    EXPECT_GE(cases, 10);
}

TEST(XformCli, BadTransformWritesNothing) {
    for (const char* bad : {"-t 1 2 scene.rad", "-s 0 scene.rad", "-rx scene.rad", "-a 2 -t 1 0 0 -mq scene.rad"}) {
        Output o = run(std::string("xform ") + bad);
        EXPECT_EQ(o.status, 1) << bad;
        EXPECT_EQ(o.out, "") << bad;
        EXPECT_EQ(o.err.rfind("xform: command line error at '-", 0), 0u) << o.err;
    }
}

TEST(XformCli, ABadLineOfAnArgumentFileWritesNothing) {
    fs::path dir = brume_test::scratchDir("xform_args");
    std::ofstream(dir / "args") << "-t 1 0 0\n-t 1 0\n";
    fs::copy_file(kData / "sub" / "part.rad", dir / "part.rad", fs::copy_options::overwrite_existing);
    Output o = run("xform -f args part.rad", dir);
    EXPECT_EQ(o.status, 1);
    EXPECT_EQ(o.out, "");
    EXPECT_EQ(o.err, "xform: command line error at '-t'\n");
}

TEST(XformCli, BadObjectIsAnErrorAtItsLine) {
    Output o = run("printf \"void plastic m 0 0 5 1 1 1 0 0\\nm polygon p 0 0 4 1 2 3 4\\n\" | xform -t 1 0 0");
    EXPECT_EQ(o.status, 1);
    EXPECT_EQ(o.err, "xform: standard input:2: bad polygon 'p': expected no strings and reals in threes\n");
    Output unknown = run("echo m blob b 0 0 0 | xform");
    EXPECT_EQ(unknown.err, "xform: standard input:1: unknown object type 'blob'\n");
}

TEST(XformCli, MissingFileIsAnError) {
    Output o = run("xform -t 1 0 0 nowhere.rad");
    EXPECT_EQ(o.status, 1);
    EXPECT_EQ(o.err, "xform: nowhere.rad: cannot find file along RAYPATH\n");
}

TEST(XformCli, FailingCommandInAFileIsAnError) {
    Output o = run("echo \"!exit 3\" | xform -e -t 1 0 0");
    EXPECT_EQ(o.status, 1);
    EXPECT_EQ(o.err, "xform: standard input:1: !exit 3: command exited with status 3\n");
}

TEST(XformCli, StandardInputCannotHoldBothArgumentsAndScene) {
    Output o = run("xform -f - < args.txt");
    EXPECT_EQ(o.status, 1);
    EXPECT_EQ(o.out, "");
    EXPECT_EQ(o.err, "xform: cannot use stdin more than once\n");
}

// Brume's own argument-file reading: quotes end at the closing quote (Radiance's stay open to the end of
// the line, which breaks every word after a quoted one).
TEST(XformCli, QuotedNamesInArgumentFiles) {
    Output o = run("echo \"-n \\\"two words\\\" -t 0 0 1\" | xform -f - sub/part.rad");
    EXPECT_EQ(o.status, 0) << o.err;
    EXPECT_NE(o.out.find("# xform -n two words.0 -t 0 0 1\n"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("m polygon \"two words.0.tri\"\n"), std::string::npos) << o.out;
}

// rtrace reads a scene whose "!xform" line must run Brume's xform: Radiance's is not on PATH.
TEST(XformCli, RtraceRunsBrumesXformForSceneCommands) {
    fs::path dir = brume_test::scratchDir("xform_scene");
    std::ofstream(dir / "lamp.rad") << "void light glow 0 0 3 1 1 1\nglow sphere bulb 0 0 4 0 0 0 .1\n";
    std::ofstream(dir / "room.rad") << "!xform -t 0 0 2 lamp.rad\n";
    Output r = brume_test::runCaptured("cd '" + dir.string() + "' && echo 0 0 0 0 0 1 | env PATH=/usr/bin:/bin '" +
                                           BRUME_BIN_DIR + "/rtrace' -h- -oLs room.rad",
                                       dir);
    EXPECT_EQ(r.status, 0) << r.err;
    std::vector<std::string> out = words(r.out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_NEAR(std::stod(out[0]), 1.9, 1e-6);  // the bulb moved up to z = 2
    EXPECT_EQ(out[1], "bulb");
}

}  // namespace
