#include "pattern/text_pattern.h"

#include <gtest/gtest.h>

#include "scene_text.h"

using namespace brume;

namespace {
std::string errorOf(const std::string& text) {
    try {
        test::TestScene s(text + "t polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST(TextPattern, BadArgumentsAreRefusedWithFileAndLine) {
    EXPECT_EQ(errorOf("void colortext t 2 helvet.fnt . 0 14 0 0 0 1 0 0 0 -1 0 1 1 1 0 0\n"),
              "test.rad:1: bad arguments for colortext \"t\": too few real arguments");
    EXPECT_EQ(errorOf("void mixtext t 3 void void helvet.fnt 0 9 0 0 0 1 0 0 0 -1 0\n"),
              "test.rad:1: bad arguments for mixtext \"t\": too few string arguments");
    EXPECT_EQ(errorOf("void brighttext t 3 helvet.fnt . Hi 0 11 0 0 0 1 0 0 2 0 0 1 0\n"),
              "test.rad:1: brighttext \"t\": illegal motion vector");  // right and down parallel
    EXPECT_EQ(errorOf("void brighttext t 2 helvet.fnt none.txt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n"),
              "test.rad:1: cannot find text file \"none.txt\"");
}
