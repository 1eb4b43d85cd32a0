// A block of text set in a font, as Radiance's text patterns set it: one line of text under another, each
// line's characters placed by a spacing rule (text_spacing.h), in font units across (255 to a character
// cell) and in lines down.
#pragma once
#include <string>
#include <vector>

#include "pattern/font.h"

namespace brume {

class TextLayout {
public:
    // `spacing` is Radiance's: the spacing argument times 255, truncated; negative squeezes the glyphs
    // -spacing apart, positive spaces them proportionally (`spacing` apart, columns kept at runs of three
    // spaces), zero puts one character in each cell. `font` must outlive the layout.
    TextLayout(const std::vector<std::string>& lines, const Font& font, int spacing);

    // Whether the point `x` font units right of the block's left edge and `y` lines below its top is
    // inside a glyph.
    bool covers(double x, double y) const;

private:
    struct Line {
        std::string text;
        std::vector<int> advances;  // see text_spacing.h
        int width = 0;
    };

    const Font* font_;
    std::vector<Line> lines_;
};

}  // namespace brume
