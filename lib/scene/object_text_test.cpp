#include "scene/object_text.h"

#include <gtest/gtest.h>

#include <sstream>

namespace brume {
namespace {

ObjectText read(const std::string& text) {
    std::istringstream in(text);
    SceneTokenizer tokens(in.rdbuf(), "t.rad");
    return ObjectWords(tokens, "t.rad").read();
}

TEST(ObjectText, ModifiersStayNamesUnresolved) {
    ObjectText o = read("undefined_yet sphere ball 0 0 4 1 2 3 .5");
    EXPECT_EQ(o.modifier, "undefined_yet");
    EXPECT_EQ(o.object.type, "sphere");
    EXPECT_EQ(o.object.name, "ball");
    EXPECT_EQ(o.object.reals, (std::vector<double>{1, 2, 3, .5}));
    EXPECT_EQ(o.object.where.str(), "t.rad:1");
}

TEST(ObjectText, AliasKeepsItsTargetAsItsOneString) {
    ObjectText o = read("inherit alias new old");
    EXPECT_EQ(o.modifier, "inherit");
    EXPECT_EQ(o.object.strings, std::vector<std::string>{"old"});
    EXPECT_EQ(objectText(o), "inherit alias new\n\told\n");
}

TEST(ObjectText, ReadingErrorsNameFileAndLine) {
    EXPECT_THROW(read("m sphere s 0 0 4 1 2"), Error);
    try {
        read("m sphere s 0 0\n4 1 2 x 1");
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "t.rad:2: bad real number 'x'");
    }
}

// Radiance's xform layout: one point per row for points (polygons, cones, rings, texts), all on the
// count's line for the rest; "%18.12g" numbers.
TEST(ObjectText, WrittenInRadianceXformLayout) {
    EXPECT_EQ(objectText(read("m polygon p 0 0 6 0 0 0 1 2 3")),
              "m polygon p\n0\n0\n6\n"
              "                  0                  0                  0\n"
              "                  1                  2                  3\n");
    EXPECT_EQ(objectText(read("m ring r 0 0 8 0 0 0 0 0 1 0 .5")),
              "m ring r\n0\n0\n8\n"
              "                  0                  0                  0\n"
              "                  0                  0                  1\n"
              "                  0                0.5\n");
    EXPECT_EQ(objectText(read("void plastic red 0 0 5 .7 .1 .1 0 0")),
              "void plastic red\n0\n0\n5                0.7                0.1                0.1                  0                  0\n");
    EXPECT_EQ(objectText(read("void spotlight s 0 0 7 1 2 3 45 0 0 -1")),
              "void spotlight s\n0\n0\n7                  1                  2                  3                 45\n"
              "\t                 0                  0                 -1\n");
}

// Radiance's xform writes these three with 6 digits only.
TEST(ObjectText, MediaAreWrittenWithSixDigitsAsRadianceDoes) {
    EXPECT_EQ(objectText(read("void dielectric w 0 0 5 .123456789 1 1 1.33 0")),
              "void dielectric w\n0\n0\n5     0.123457            1            1         1.33            0\n");
    EXPECT_EQ(objectText(read("void interface i 0 0 8 1 1 1 1 .9 .9 .9 1.5")),
              "void interface i\n0\n0\n8\n"
              "           1            1            1            1\n"
              "         0.9          0.9          0.9          1.5\n");
}

TEST(ObjectText, WordsWithSpacesOrInnerQuotesAreQuoted) {
    EXPECT_EQ(objectText(read("void brighttext t 3 f.fnt \"two words\" \"it's\" 0 0")),
              "void brighttext t\n3 f.fnt \"two words\" \"it's\"\n0\n0\n");
}

TEST(ObjectText, WrittenTextReadsBackTheSame) {
    ObjectText o = read("m cone c 0 0 8 0.1 -2e-7 3 4 5 6 .25 1e10");
    ObjectText again = read(objectText(o));
    EXPECT_EQ(again.object.reals, o.object.reals);
    EXPECT_EQ(again.modifier, o.modifier);
}

}  // namespace
}  // namespace brume
