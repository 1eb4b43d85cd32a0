// Where the characters of a line of text go, in font units (a character cell is 255 wide), by Radiance's
// three spacing rules (reference manual, "Colortext"; "File Formats", "Font File Format"). Each returns the
// advances a[0 … n]: character i starts at a[0] + … + a[i], and the line is a[0] + … + a[n] long.
// Characters without a glyph in the font take no room.
#pragma once
#include <string>
#include <vector>

#include "pattern/font.h"

namespace brume {

// Every character with a glyph in a cell of its own: each at a predictable place.
std::vector<int> uniformSpacing(const std::string& line, const Font& font);

// Glyphs `gap` apart, edge to edge (a space as wide as the font's mean glyph): good-looking words whose
// places depend on the glyphs' widths.
std::vector<int> squeezedSpacing(const std::string& line, const Font& font, int gap);

// Squeezed, then stretched or shrunk piecewise so that each stretch of text ends where it would with
// `gap` around mean-width glyphs; a stretch ends after `indent` or more spaces in a row, which keeps
// columns and indents of formatted text in place.
std::vector<int> proportionalSpacing(const std::string& line, const Font& font, int gap, int indent);

}  // namespace brume
