#include "cal/lexer.h"

#include <cctype>
#include <charconv>

namespace brume::cal {

namespace {

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)); }

std::string describe(const Token& t) {
    if (t.kind == Token::Kind::End) return "end of text";
    if (std::isprint(static_cast<unsigned char>(t.text[0]))) return "'" + std::string(t.text) + "'";
    return "character code " + std::to_string(static_cast<unsigned char>(t.text[0]));
}

}  // namespace

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '`'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '`'; }

Lexer::Lexer(std::string_view text, std::string file, int firstLine)
    : text_(text), file_(std::move(file)), line_(firstLine) {
    scan();
}

Token Lexer::next() {
    Token t = token_;
    scan();
    return t;
}

void Lexer::fail(const std::string& what) const {
    throw Error({file_, token_.line}, what + ", found " + describe(token_));
}

void Lexer::skipSpaceAndComments() {
    for (int depth = 0, opened = 0; pos_ < text_.size(); ++pos_) {
        char c = text_[pos_];
        if (c == '\n' && line_ > 0) ++line_;
        if (c == '{' && depth++ == 0)
            opened = line_;
        else if (c == '}' && depth > 0)
            --depth;
        else if (depth == 0 && !std::isspace(static_cast<unsigned char>(c)))
            return;
        if (depth > 0 && pos_ + 1 == text_.size()) throw Error({file_, opened}, "comment '{' is never closed");
    }
}

void Lexer::scan() {
    skipSpaceAndComments();
    token_ = Token();
    token_.line = line_;
    if (pos_ == text_.size()) return;
    size_t start = pos_;
    char c = text_[pos_];
    if (isDigit(c) || c == '.') {
        scanNumber();
    } else if (isNameStart(c)) {
        while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
        token_.kind = Token::Kind::Name;
        token_.text = text_.substr(start, pos_ - start);
    } else if (c == '$') {
        // Radiance allows space between '$' and the number.
        ++pos_;
        skipSpaceAndComments();
        size_t digits = pos_;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
        token_.kind = Token::Kind::Channel;
        token_.text = text_.substr(start, pos_ - start);
        auto [end, ec] = std::from_chars(text_.data() + digits, text_.data() + pos_, token_.channel);
        if (pos_ == digits) fail("channel number expected after '$'");
        if (ec != std::errc()) fail("channel number out of range");
    } else {
        ++pos_;
        token_.kind = Token::Kind::Symbol;
        token_.text = text_.substr(start, 1);
    }
}

// Radiance's number syntax: digits [. digits] [e [sign] digits], with a digit before or after the point;
// no sign (unary minus is an operator).
void Lexer::scanNumber() {
    size_t start = pos_;
    auto digits = [&] {
        size_t from = pos_;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
        return pos_ - from;
    };
    size_t mantissa = digits();
    if (pos_ < text_.size() && text_[pos_] == '.') {
        ++pos_;
        mantissa += digits();
    }
    token_.kind = Token::Kind::Number;
    token_.text = text_.substr(start, pos_ - start);
    if (mantissa == 0) fail("badly formed number");
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
        ++pos_;
        if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
        token_.text = text_.substr(start, pos_ - start);
        if (digits() == 0) fail("missing exponent in number");
        token_.text = text_.substr(start, pos_ - start);
    }
    auto [end, ec] = std::from_chars(token_.text.data(), token_.text.data() + token_.text.size(), token_.number);
    // from_chars reports underflow and overflow alike; a tiny number is zero, a huge one an error.
    bool tiny = token_.text.find("e-") != std::string_view::npos || token_.text.find("E-") != std::string_view::npos;
    if (ec == std::errc::result_out_of_range && tiny)
        token_.number = 0;
    else if (ec != std::errc())
        fail("number out of range");
}

}  // namespace brume::cal
