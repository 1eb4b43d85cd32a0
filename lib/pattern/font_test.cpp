#include "pattern/font.h"

#include <gtest/gtest.h>

#include "scene_text.h"

using namespace brume;

namespace {

std::string errorOf(const std::string& text) {
    try {
        Font::parse(text, "f.fnt");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// A 200 × 200 square with a 100 × 100 hole, joined to its outline by a seam from (20, 20) to (70, 70).
const char* kSquareWithHole = "65 10  20 20  220 20  220 220  20 220  20 20  70 70  70 170  170 170  170 70  70 70\n";

}  // namespace

TEST(Font, ReadsGlyphsSpacesAndComments) {
    Font f = Font::parse(std::string("# a comment\n") + kSquareWithHole + "32 0  # space\n66 3 10 10 60 10 60 60#x\n",
                         "f.fnt");
    ASSERT_TRUE(f.glyph('A'));
    EXPECT_EQ(f.glyph('A')->left(), 20);
    EXPECT_EQ(f.glyph('A')->top(), 220);
    EXPECT_TRUE(f.glyph(' ')->isSpace());
    EXPECT_EQ(f.glyph('C'), nullptr);
    // Radiance measures extents from the grid's centre out: "B" reaches 128 to the right and up.
    EXPECT_EQ(f.glyph('B')->right(), 128);
    EXPECT_EQ(f.glyph('B')->top(), 128);
    EXPECT_EQ(f.meanWidth(), (200 + 118) / 2);  // the space is not measured
}

TEST(Font, GlyphsAreFilledByTheEvenOddRuleWithSeams) {
    Font f = Font::parse(kSquareWithHole, "f.fnt");
    const Glyph& a = *f.glyph('A');
    EXPECT_TRUE(a.covers(40.3, 120.7));    // the frame, left
    EXPECT_TRUE(a.covers(200.5, 30.2));    // the frame, lower right
    EXPECT_FALSE(a.covers(120.5, 120.5));  // the hole
    EXPECT_FALSE(a.covers(10.5, 120.5));   // outside
    EXPECT_FALSE(a.covers(230.5, 120.5));
    EXPECT_TRUE(a.covers(60.5, 40.5));     // beside the seam, on both sides: the seam takes nothing away
    EXPECT_TRUE(a.covers(40.5, 60.5));
}

TEST(Font, MalformedFilesAreRefusedWithFileAndLine) {
    EXPECT_EQ(errorOf("65 3 0 0 1 1 2 2\n65 0\n"), "f.fnt:2: duplicate character (65)");
    EXPECT_EQ(errorOf("0 0\n"), "f.fnt:1: illegal character (0)");
    EXPECT_EQ(errorOf("\n256 0\n"), "f.fnt:2: illegal character (256)");
    EXPECT_EQ(errorOf("65 x\n"), "f.fnt:1: bad # vertices for character (65)");
    EXPECT_EQ(errorOf("65 -1\n"), "f.fnt:1: bad # vertices for character (65)");
    EXPECT_EQ(errorOf("65 2 0 0\n1 256\n"), "f.fnt:2: bad vertex for character (65)");
    EXPECT_EQ(errorOf("65 2 0 0\n1"), "f.fnt:2: bad vertex for character (65)");  // cut short
    EXPECT_EQ(errorOf("# fine\nA 0\n"), "f.fnt:2: non-integer in font file");
}

// Brume ships its own helvet.fnt (lib/pattern/fonts), found when RAYPATH has none.
TEST(Font, BrumesOwnFontIsFoundWithoutRadiance) {
    test::ScopedRayPath path("/nonexistent");
    Font f = loadFont("helvet.fnt", {});
    for (int c = '!'; c <= '~'; ++c) EXPECT_TRUE(f.glyph((unsigned char)c) && !f.glyph((unsigned char)c)->isSpace()) << c;
    EXPECT_TRUE(f.glyph(' ')->isSpace());
    try {
        loadFont("nofont.fnt", {"s.rad", 3});
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "s.rad:3: cannot find font file \"nofont.fnt\"");
    }
}
