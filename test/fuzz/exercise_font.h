// What the font fuzz target and the corpus replay do with an input: read it as a font file and, if it
// reads, test points all over every glyph's grid (the row index and the even-odd test) and set a line in it
// by each spacing rule.
#pragma once
#include <string>

#include "pattern/font.h"
#include "pattern/text_layout.h"

namespace brume::fuzz {

inline void exerciseFont(const std::string& text) {
    Font font = Font::parse(text, "fuzz.fnt");
    for (int c = 1; c < 256; ++c)
        if (const Glyph* g = font.glyph((unsigned char)c))
            for (double y = 0.5; y < 255; y += 7.3)
                for (double x = 0.25; x < 255; x += 5.1) g->covers(x, y);
    std::string line;
    for (int c = 1; c < 256; ++c) line += char(c);
    for (int spacing : {0, -40, 40}) {
        TextLayout layout({line, "  a   b"}, font, spacing);
        for (double x = 0; x < 255 * 300; x += 97.3) layout.covers(x, 0.5), layout.covers(x, 1.5);
    }
}

}  // namespace brume::fuzz
