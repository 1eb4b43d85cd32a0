#include "pattern/text_layout.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pattern/test_font.h"

using namespace brume;

namespace {
const Font& font() { return test::barsFont(); }
}  // namespace

// Uniform cells of 255 across and lines one unit down; a glyph's y runs up from its line's bottom.
TEST(TextLayout, UniformCellsAndLines) {
    TextLayout t({"IW", "W"}, font(), 0);
    EXPECT_TRUE(t.covers(125, 0.5));       // "I"
    EXPECT_FALSE(t.covers(60, 0.5));       // beside it
    EXPECT_FALSE(t.covers(125, 0.05));     // above it (y 242 of 255)
    EXPECT_TRUE(t.covers(125, 0.85));      // near its bottom (y 38)
    EXPECT_TRUE(t.covers(255 + 20, 0.5));  // "W"
    EXPECT_TRUE(t.covers(20, 1.5));        // second line's "W"
    EXPECT_FALSE(t.covers(255 + 20, 1.5)); // past the second line's end
    EXPECT_FALSE(t.covers(20, 2.5));       // no third line
    EXPECT_FALSE(t.covers(-5, 0.5));
    EXPECT_FALSE(t.covers(std::nan(""), 0.5));
}

// Squeezed by 20 (spacing -20): "I" at 20…70, "W" at 90…320.
TEST(TextLayout, SqueezedGlyphsSitAGapApart) {
    TextLayout t({"IW"}, font(), -20);
    EXPECT_TRUE(t.covers(25, 0.5));
    EXPECT_FALSE(t.covers(80, 0.5));
    EXPECT_TRUE(t.covers(95, 0.5));
    EXPECT_TRUE(t.covers(315, 0.5));
    EXPECT_FALSE(t.covers(325, 0.5));
}
