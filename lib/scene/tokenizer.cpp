#include "scene/tokenizer.h"

#include <cctype>

#include "util/error.h"

namespace brume {

namespace {

constexpr int kEof = std::char_traits<char>::eof();

bool isSpace(int c) { return c != kEof && std::isspace(static_cast<unsigned char>(c)); }
bool isQuote(int c) { return c == '"' || c == '\''; }

}  // namespace

int SceneTokenizer::get() {
    int c = in_->sbumpc();
    if (c == '\n') ++line_;
    return c;
}

int SceneTokenizer::peek() {
    while (isSpace(in_->sgetc())) get();
    return in_->sgetc();
}

std::optional<SceneTokenizer::Word> SceneTokenizer::next() {
    if (peek() == kEof) return std::nullopt;
    Word word{{}, line_};
    int quote = 0, quoteLine = 0;
    for (int c = get(); c != kEof; c = get()) {
        if (c == quote) {
            quote = 0;
        } else if (!quote && isQuote(c)) {
            quote = c, quoteLine = line_;
        } else if (!quote && isSpace(c)) {
            break;
        } else {
            word.text += static_cast<char>(c);
        }
    }
    if (quote) throw Error(SourceLocation{name_, quoteLine}, "unterminated quote");
    return word;
}

std::string SceneTokenizer::restOfLine(bool continued) {
    std::string text;
    for (int c = get(); c != kEof; c = get()) {
        if (c == '\r' && in_->sgetc() == '\n') continue;  // DOS line end
        if (c == '\n' && !(continued && text.ends_with('\\'))) break;
        text += static_cast<char>(c);
    }
    return text;
}

}  // namespace brume
