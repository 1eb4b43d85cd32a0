#include "cal/library.h"

#include <gtest/gtest.h>

#include "cal/testing.h"
#include "ray_path_dir.h"

namespace brume::cal {
namespace {

using testing::Calc;

TEST(CalLibrary, FilesHaveTheirOwnContextAsInRadiance) {
    EXPECT_EQ(scopeOfFile("skybright.cal").context, "`skybright");
    EXPECT_EQ(scopeOfFile("../lib/my file.CAL").context, "`.._lib_my_file");
    EXPECT_EQ(scopeOfFile(".").context, "");
}

TEST(CalLibrary, AFileIsFoundOnRayPathAndLoadedOnce) {
    RayPathDir dir;
    dir.write("mine.cal", "val = 1;");
    Calc calc;
    Scope scope = calc.library.loadFile("mine.cal");
    dir.write("mine.cal", "val = 2;");
    calc.library.loadFile("mine.cal");
    EXPECT_EQ(calc("val", scope), 1);
}

TEST(CalLibrary, RayPathComesBeforeTheStandardLibrary) {
    RayPathDir dir;
    dir.write("tilt.cal", "tilt_ang = 42;");
    Calc calc;
    EXPECT_EQ(calc("tilt_ang", calc.library.loadFile("tilt.cal")), 42);
}

TEST(CalLibrary, TheStandardLibraryIsFoundWhenRayPathHasNothing) {
    RayPathDir dir;
    Calc calc;
    calc.channels[Kz] = 1;
    EXPECT_EQ(calc("tilt_ang", calc.library.loadFile("tilt.cal")), 0);
}

TEST(CalLibrary, NamesOfTwoFilesDoNotClash) {
    RayPathDir dir;
    dir.write("a.cal", "u = 1; fa = u + g;");
    dir.write("b.cal", "u = 2; fb = u + g;");
    Calc calc;
    calc.library.loadText("g = 10;", "global");
    Scope a = calc.library.loadFile("a.cal"), b = calc.library.loadFile("b.cal");
    EXPECT_EQ(calc("fa + u", a), 12);
    EXPECT_EQ(calc("fb + u", b), 14);
    EXPECT_EQ(calc.error("fa"), "test:1: undefined variable 'fa'");
}

TEST(CalLibrary, ContextMarksChooseGlobalOrLocalNames) {
    Calc calc;
    Scope local{"`here"};
    calc.library.loadText("x = 1; y = 5;", "global");
    calc.library.loadText("x = 2; z` = 3; `w = 4;", "here", local);
    EXPECT_EQ(calc("x", local), 2);
    EXPECT_EQ(calc("x`", local), 1);  // explicitly global
    EXPECT_EQ(calc("z"), 3);          // defined as global
    EXPECT_EQ(calc("w + `w + y", local), 13);
    EXPECT_EQ(calc.error("`y", local), "test:1: undefined variable '`y'");  // local only
}

TEST(CalLibrary, AMissingFileIsAnErrorNamingTheReference) {
    RayPathDir dir;
    Library library;
    try {
        library.loadFile("nowhere.cal", {"scene.rad", 7});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "scene.rad:7: cannot find function file \"nowhere.cal\"");
    }
}

TEST(CalLibrary, AFileWithASyntaxErrorDefinesNothing) {
    RayPathDir dir;
    dir.write("bad.cal", "good = 1;\nbad = ;");
    Calc calc;
    try {
        calc.library.loadFile("bad.cal");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.cal:2: expression expected"), std::string::npos);
    }
    EXPECT_EQ(calc.error("good", scopeOfFile("bad.cal")), "test:1: undefined variable 'good'");
}

}  // namespace
}  // namespace brume::cal
