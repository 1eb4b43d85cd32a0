#include "pattern/text_spacing.h"

namespace brume {

std::vector<int> uniformSpacing(const std::string& line, const Font& font) {
    std::vector<int> a(line.size() + 1, 0);
    for (size_t i = 0; i < line.size(); ++i) a[i + 1] = font.glyph((unsigned char)line[i]) ? 255 : 0;
    return a;
}

// A pen moves along the line: it starts half a gap in; each glyph's left edge goes half a gap past it, and
// it then moves half a gap past the glyph's right edge (a space: the mean width past the space's start); the
// line ends half a gap past it. a[i + 1] holds the pen's distance from character i's start, to which the
// next glyph adds its own offset; characters without a glyph sit at the pen.
std::vector<int> squeezedSpacing(const std::string& line, const Font& font, int gap) {
    int half = gap / 2;
    std::vector<int> a(line.size() + 1, 0);
    size_t pen = 0;  // the slot holding the pen's distance from the last placed character
    while (pen < line.size() && !font.glyph((unsigned char)line[pen])) ++pen;
    a[pen] = half;
    for (size_t i = pen; i < line.size(); ++i) {
        const Glyph* g = font.glyph((unsigned char)line[i]);
        if (!g) continue;
        if (!g->isSpace()) a[i] += half - g->left();
        a[i + 1] = g->isSpace() ? font.meanWidth() : g->right() + half;
    }
    size_t last = line.size();
    a[last] += half;
    return a;
}

namespace {

bool isSpace(const Font& font, char c) {
    const Glyph* g = font.glyph((unsigned char)c);
    return g && g->isSpace();
}

// The end of the stretch of text from `begin`: just after a character with a glyph and the spaces that
// follow it, when there are `indent` or more of them; `glyphs` counts the characters with glyphs in it.
size_t stretchEnd(const std::string& line, const Font& font, size_t begin, int indent, int& glyphs) {
    glyphs = 0;
    for (size_t i = begin; i < line.size();) {
        size_t next = i + 1;
        if (font.glyph((unsigned char)line[i])) {
            while (next < line.size() && isSpace(font, line[next])) ++next;
            glyphs += int(next - i);
        }
        if (indent && int(next - i) > indent) return next;
        i = next;
    }
    return line.size();
}

}  // namespace

std::vector<int> proportionalSpacing(const std::string& line, const Font& font, int gap, int indent) {
    std::vector<int> a = squeezedSpacing(line, font, gap);
    for (size_t begin = 0; begin < line.size();) {
        int glyphs = 0;
        size_t end = stretchEnd(line, font, begin, indent, glyphs);
        // The pen's moves after characters begin … end-1 (a[begin+1 … end]) share out the difference
        // between the stretch's length at mean width and its squeezed length, in integer parts.
        int squeezed = 0;
        for (size_t k = begin + 1; k <= end; ++k) squeezed += a[k];
        int excess = glyphs * (font.meanWidth() + gap) - squeezed;
        for (size_t k = begin + 1; k <= end; ++k) {
            int share = excess / int(end + 1 - k);
            a[k] += share;
            excess -= share;
        }
        begin = end;
    }
    return a;
}

}  // namespace brume
