#include "pattern/font.h"

#include <algorithm>
#include <charconv>

#include "pattern/embedded_fonts.h"
#include "scene/raypath.h"

namespace brume {

Glyph::Glyph(std::vector<uint8_t> xy) : xy_(std::move(xy)) {
    for (int i = 0; i < vertexCount(); ++i) {
        left_ = std::min(left_, x(i)), right_ = std::max(right_, x(i));
        bottom_ = std::min(bottom_, y(i)), top_ = std::max(top_, y(i));
    }
    indexRows();
}

void Glyph::indexRows() {
    int n = vertexCount();
    rowStart_.assign(size_t(top_ - bottom_ + 1), 0);
    std::vector<std::vector<uint16_t>> rows(size_t(top_ - bottom_));
    for (int i = 0; i < n; ++i) {
        int j = (i + 1) % n;
        // The edge crosses the mid-heights of the rows from its lower end's up to below its upper end's.
        for (int r = std::min(y(i), y(j)); r < std::max(y(i), y(j)); ++r) rows[size_t(r - bottom_)].push_back(uint16_t(i));
    }
    for (size_t r = 0; r < rows.size(); ++r) {
        rowEdges_.insert(rowEdges_.end(), rows[r].begin(), rows[r].end());
        rowStart_[r + 1] = uint32_t(rowEdges_.size());
    }
}

bool Glyph::covers(double px, double py) const {
    int cx = int(px), cy = int(py);
    if (cx < left_ || cx >= right_ || cy < bottom_ || cy >= top_) return false;
    int n = vertexCount();
    bool inside = false;
    for (uint32_t k = rowStart_[size_t(cy - bottom_)]; k < rowStart_[size_t(cy - bottom_) + 1]; ++k) {
        int i = rowEdges_[k], j = (i + 1) % n;
        bool rightI = x(i) > cx, rightJ = x(j) > cx;  // of the cell's centre: beyond cx + 1/2
        if (rightI && rightJ) {
            inside = !inside;
        } else if (rightI || rightJ) {
            // Whether the edge passes to the right of the point; on the edge, upward edges count.
            double cross = (x(i) - px) * (y(j) - py) - (y(i) - py) * (x(j) - px);
            if (y(j) > y(i) ? cross >= 0 : cross < 0) inside = !inside;
        }
    }
    return inside;
}

namespace {

// The whitespace-separated words of a font file, '#' starting a comment to the end of the line.
class Words {
public:
    Words(std::string_view text, const std::string& origin) : text_(text), origin_(origin) {}

    enum class Read { End, Integer, Other };
    // The next word, as an integer if it is one.
    Read next(int& value) {
        skipSpaceAndComments();
        if (at_ == text_.size()) return Read::End;
        size_t start = at_;
        while (at_ < text_.size() && !std::isspace((unsigned char)text_[at_]) && text_[at_] != '#') ++at_;
        const char* first = text_.data() + start + (text_[start] == '+');
        const char* last = text_.data() + at_;
        auto [end, ec] = std::from_chars(first, last, value);
        return ec == std::errc() && end == last && first != last ? Read::Integer : Read::Other;
    }
    [[noreturn]] void fail(const std::string& what) const { throw Error(SourceLocation{origin_, line_}, what); }

private:
    void skipSpaceAndComments() {
        while (at_ < text_.size()) {
            char c = text_[at_];
            if (c == '#') {
                while (at_ < text_.size() && text_[at_] != '\n') ++at_;
            } else if (std::isspace((unsigned char)c)) {
                line_ += c == '\n';
                ++at_;
            } else {
                return;
            }
        }
    }

    std::string_view text_;
    std::string origin_;
    size_t at_ = 0;
    int line_ = 1;
};

// One glyph's vertex list after its code: the count, then x y pairs.
std::vector<uint8_t> readVertices(Words& words, int code) {
    int count = 0;
    if (words.next(count) != Words::Read::Integer || count < 0 || count > 32000)
        words.fail("bad # vertices for character (" + std::to_string(code) + ")");
    std::vector<uint8_t> xy(2 * size_t(count));
    for (uint8_t& v : xy) {
        int value = 0;
        if (words.next(value) != Words::Read::Integer || value < 0 || value > 255)
            words.fail("bad vertex for character (" + std::to_string(code) + ")");
        v = uint8_t(value);
    }
    return xy;
}

}  // namespace

Font Font::parse(std::string_view text, const std::string& origin) {
    Font font;
    Words words(text, origin);
    int widths = 0, heights = 0, measured = 0;
    int code = 0;
    for (Words::Read r; (r = words.next(code)) != Words::Read::End;) {
        if (r != Words::Read::Integer) words.fail("non-integer in font file");
        if (code < 1 || code > 255) words.fail("illegal character (" + std::to_string(code) + ")");
        if (font.glyphs_[size_t(code)]) words.fail("duplicate character (" + std::to_string(code) + ")");
        auto g = std::make_unique<const Glyph>(readVertices(words, code));
        if (g->right() > g->left() && g->top() > g->bottom()) {
            widths += g->right() - g->left(), heights += g->top() - g->bottom();
            ++measured;
        }
        font.glyphs_[size_t(code)] = std::move(g);
    }
    if (measured) font.meanWidth_ = widths / measured, font.meanHeight_ = heights / measured;
    return font;
}

Font loadFont(const std::string& name, const SourceLocation& where) {
    FileText file = readLibraryFile(name, embeddedFontFiles(), "font file", where);
    return Font::parse(file.text, file.origin);
}

}  // namespace brume
