#include "scene/xform_command.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace brume {
namespace {

using Args = std::vector<std::string>;

// The runs a command line stands for: each run's words, or "echo: <line>".
std::vector<std::string> runs(const Args& argv) {
    std::vector<std::string> out;
    XformExpansion expansion;
    expansion.forEachRun(argv, [&](const XformRun& run) {
        if (run.args.empty()) return out.push_back("echo: " + run.echo);
        std::string line;
        for (const std::string& a : run.args) line += (line.empty() ? "" : " ") + a;
        out.push_back(line);
    });
    return out;
}

std::string argumentFile(const std::string& text) {
    std::string path = std::filesystem::temp_directory_path() / ("brume_xform_args_" + std::to_string(getpid()));
    std::ofstream(path) << text;
    return path;
}

TEST(XformCommand, ArrayCopiesStepByTheTransformAndAreNamedByIndex) {
    EXPECT_EQ(runs({"xform", "-a", "3", "-t", "1", "0", "0", "f.rad"}),
              (std::vector<std::string>{"xform -n a0 -i 0 -t 1 0 0 f.rad", "xform -n a1 -i 1 -t 1 0 0 f.rad",
                                        "xform -n a2 -i 2 -t 1 0 0 f.rad"}));
}

TEST(XformCommand, TwoArraysMakeAGridWithCompoundNames) {
    std::vector<std::string> r = runs({"xform", "-n", "lamp", "-a", "2", "-t", "1", "0", "0", "-a", "2", "-ry", "90"});
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r[0], "xform -n lamp.0.0 -i 0 -t 1 0 0 -i 0 -ry 90");
    EXPECT_EQ(r[3], "xform -n lamp.1.1 -i 1 -t 1 0 0 -i 1 -ry 90");
}

TEST(XformCommand, ArgumentFileLinesAreRunsAndCommentsPassOn) {
    std::string file = argumentFile("# copies\n-t 1 0 0\n\n!xform -n x -rz 90\nxform -n \"a b\" -s 2 \\\n -mx\n");
    EXPECT_EQ(runs({"xform", "-c", "-f", file, "part.rad"}),
              (std::vector<std::string>{"echo: # copies", "xform -n i0 -c -t 1 0 0 part.rad", "echo: ",
                                        "xform -c -n x.1 -rz 90 part.rad", "xform -c -n a b.2 -s 2 -mx part.rad"}));
    std::filesystem::remove(file);
}

TEST(XformCommand, MissingCountsAndFilesAreErrors) {
    EXPECT_THROW(runs({"xform", "-a", "0", "-t", "1", "0", "0"}), Error);
    EXPECT_THROW(runs({"xform", "-t", "1", "0", "0", "-a"}), Error);
    EXPECT_THROW(runs({"xform", "-f"}), Error);
    EXPECT_THROW(runs({"xform", "-f", "/nonexistent/args"}), Error);
    std::string empty = argumentFile("# nothing but a comment\n\n");
    EXPECT_THROW(runs({"xform", "-f", empty}), Error);
    std::string loop = argumentFile("-t 1 0 0\n-f " + empty + "\n");  // the same file, rewritten
    EXPECT_THROW(runs({"xform", "-f", loop}), Error);
    std::filesystem::remove(loop);
}

TEST(XformCommand, OptionsTransformAndFilesAreSeparated) {
    XformCommand c = parseXformCommand({"xform", "-n", "a", "-n", "b", "-m", "m1", "-m", "m2", "-I", "-c", "-rz",
                                        "90", "-t", "1", "0", "0", "x.rad", "y.rad"});
    EXPECT_EQ(c.transform.objects.prefix, "a.b");
    EXPECT_EQ(c.transform.objects.modifier, "m1");
    EXPECT_TRUE(c.transform.objects.invert);
    EXPECT_FALSE(c.transform.expandCommands);
    EXPECT_EQ(c.transform.objects.words, (Args{"-rz", "90", "-t", "1", "0", "0"}));
    EXPECT_EQ(c.files, (Args{"x.rad", "y.rad"}));
    EXPECT_EQ(c.header, "# xform -n a -n b -m m1 -m m2 -I -c -rz 90 -t 1 0 0");
    // Commands passed on are transformed later by the same command, less -c and the files.
    EXPECT_EQ(c.transform.commandPipe, " | xform -e -n a -n b -m m1 -m m2 -I -rz 90 -t 1 0 0");
}

TEST(XformCommand, NoArgumentsReadTheStandardInputUnchanged) {
    XformCommand c = parseXformCommand({"xform"});
    EXPECT_TRUE(c.files.empty());
    EXPECT_EQ(c.header, "# xform");
    EXPECT_EQ(c.transform.commandPipe, "");
}

TEST(XformCommand, BadTransformIsACommandLineError) {
    for (Args args : {Args{"xform", "-t", "1", "2", "f.rad"}, Args{"xform", "-s", "0", "f.rad"},
                      Args{"xform", "-rz", "x", "f.rad"}, Args{"xform", "-q", "f.rad"}}) {
        try {
            parseXformCommand(args);
            ADD_FAILURE() << args[1] << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.what(), "command line error at '" + args[1] + "'");
        }
    }
}

}  // namespace
}  // namespace brume
