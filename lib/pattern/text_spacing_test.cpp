#include "pattern/text_spacing.h"

#include <gtest/gtest.h>

#include "pattern/test_font.h"

using namespace brume;

namespace {
const Font& font() { return test::barsFont(); }
using V = std::vector<int>;
}  // namespace

TEST(TextSpacing, UniformGivesEveryGlyphACell) {
    EXPECT_EQ(uniformSpacing("I?W", font()), (V{0, 255, 0, 255}));  // "?" has no glyph: it takes no room
}

// Glyphs' edges 20 apart and 20 from the line's ends: "I" at 20…70, "W" at 90…320, 340 long.
TEST(TextSpacing, SqueezedPutsGlyphEdgesAGapApart) {
    EXPECT_EQ(squeezedSpacing("IW", font(), 20), (V{-80, 160, 260}));
    EXPECT_EQ(squeezedSpacing("I?W", font(), 20), (V{-80, 160, 0, 260}));
    EXPECT_EQ(squeezedSpacing("I W", font(), 20), (V{-80, 160, 140, 260}));  // a space: the mean width
    EXPECT_EQ(squeezedSpacing("", font(), 20), (V{20}));
}

// Three characters at mean width and gap: 480 after the first edge; the squeezed 560 shrunk in integer
// shares, -26, -27, -27.
TEST(TextSpacing, ProportionalKeepsTheLengthOfMeanGlyphs) {
    EXPECT_EQ(proportionalSpacing("I W", font(), 20, 3), (V{-80, 134, 113, 233}));
}

// After four spaces a new stretch starts where five mean characters would have taken the pen: "W" starts
// at -80 + 5 × 160 whatever the widths before it.
TEST(TextSpacing, ProportionalKeepsColumnsAfterRunsOfSpaces) {
    V a = proportionalSpacing("I    W", font(), 20, 3);
    int start = 0;
    for (size_t i = 0; i <= 5; ++i) start += a[i];
    EXPECT_EQ(start, -80 + 5 * 160);
    EXPECT_EQ(a[6], 140 + 20);  // the last stretch: one glyph at mean width and gap
}
