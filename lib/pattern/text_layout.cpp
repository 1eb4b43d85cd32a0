#include "pattern/text_layout.h"

#include <numeric>

#include "pattern/text_spacing.h"

namespace brume {

namespace {
constexpr int kIndentSpaces = 3;  // Radiance's text patterns keep columns after this many spaces
constexpr int kCell = 255;        // a glyph's cell, in font units
}  // namespace

TextLayout::TextLayout(const std::vector<std::string>& lines, const Font& font, int spacing) : font_(&font) {
    for (const std::string& text : lines) {
        Line line{text, {}, 0};
        if (spacing < 0) line.advances = squeezedSpacing(text, font, -spacing);
        else if (spacing > 0) line.advances = proportionalSpacing(text, font, spacing, kIndentSpaces);
        else line.advances = uniformSpacing(text, font);
        line.width = std::accumulate(line.advances.begin(), line.advances.end(), 0);
        lines_.push_back(std::move(line));
    }
}

bool TextLayout::covers(double x, double y) const {
    if (!(x >= 0 && y >= 0 && y < double(lines_.size()))) return false;  // NaN too
    size_t row = size_t(y);
    const Line& line = lines_[row];
    if (x >= line.width) return false;
    int h = int(x);
    double across = x - h, up = (double(row + 1) - y) * kCell;  // within the cell; glyphs' y is up
    // Characters in order until one starts past the point (glyphs may overlap when squeezed, so every one
    // that started less than a cell before is tried).
    for (size_t i = 0; i < line.text.size(); ++i) {
        h -= line.advances[i];
        if (h < 0) break;
        const Glyph* g = font_->glyph((unsigned char)line.text[i]);
        if (h < kCell && g && g->covers(h + across, up)) return true;
    }
    return false;
}

}  // namespace brume
