// Radiance's polygonal fonts (.fnt; Radiance's "File Formats", "Font File Format"): each character a
// polygon on a 0–255 grid, x to the right and y up, holes and separate parts joined by seams, inside by the
// even-odd rule. Text patterns and mixtures write with them.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace brume {

class Glyph {
public:
    explicit Glyph(std::vector<uint8_t> xy);  // x0 y0 x1 y1 …

    // A glyph without vertices is a space: it takes room and covers nothing.
    bool isSpace() const { return xy_.empty(); }
    // The extent of the vertices and of the grid's centre 128 (as Radiance measures it).
    int left() const { return left_; }
    int right() const { return right_; }
    int bottom() const { return bottom_; }
    int top() const { return top_; }

    // Whether (x, y), in [0, 255), is inside: Radiance's test, which takes the row of the grid cell holding
    // the point at its mid-height and decides by the cell's centre which edges lie to the right of the point,
    // and by the point itself only for the edges that pass through its cell's row beside it.
    bool covers(double x, double y) const;

private:
    int vertexCount() const { return int(xy_.size() / 2); }
    int x(int i) const { return xy_[2 * size_t(i)]; }
    int y(int i) const { return xy_[2 * size_t(i) + 1]; }
    void indexRows();

    std::vector<uint8_t> xy_;
    int left_ = 128, right_ = 128, bottom_ = 128, top_ = 128;
    // The edges that cross each row of cells from bottom_ to top_ (edge i joins vertex i to i+1), so a test
    // looks at a few edges, not all: row r's are rowEdges_[rowStart_[r - bottom_] … rowStart_[r - bottom_ + 1]).
    std::vector<uint32_t> rowStart_;
    std::vector<uint16_t> rowEdges_;
};

class Font {
public:
    // Reads a font file's text; `origin` names it in messages. Throws Error ("origin:line: what") for a
    // word that is not an integer, a character code outside 1…255 or given twice, a bad vertex count or a
    // vertex outside 0…255.
    static Font parse(std::string_view text, const std::string& origin);

    // The character's glyph, or nullptr when the font has none (the character is skipped).
    const Glyph* glyph(unsigned char c) const { return glyphs_[c].get(); }
    // The mean width and height of the glyphs with some extent (integer division, as Radiance's).
    int meanWidth() const { return meanWidth_; }
    int meanHeight() const { return meanHeight_; }

private:
    std::array<std::unique_ptr<const Glyph>, 256> glyphs_;
    int meanWidth_ = 0, meanHeight_ = 0;
};

// The font file `name`, found along RAYPATH, else among Brume's own fonts (lib/pattern/fonts). Throws Error
// (at `where`) when it is in neither, or is malformed.
Font loadFont(const std::string& name, const SourceLocation& where);

}  // namespace brume
