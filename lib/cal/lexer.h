// Tokens of the .cal language: numbers, names, $channels and one-character symbols, with { nested
// comments } and white space between them.
#pragma once
#include <string>
#include <string_view>

#include "util/error.h"

namespace brume::cal {

struct Token {
    enum class Kind { End, Number, Name, Channel, Symbol };
    Kind kind = Kind::End;
    std::string_view text;
    double number = 0;  // Number
    int channel = 0;    // Channel
    int line = 0;
    bool is(char symbol) const { return kind == Kind::Symbol && text[0] == symbol; }
};

// Radiance's identifier characters (calcomp.h's isid): a name starts with a letter or the context mark '`'.
bool isNameStart(char c);
bool isNameChar(char c);

class Lexer {
public:
    // `firstLine` is the line number of the text's first line (0: not counted, as for one expression).
    Lexer(std::string_view text, std::string file, int firstLine);

    const Token& peek() const { return token_; }
    Token next();
    // A syntax error at the current token: "file:line: what, found 'token'".
    [[noreturn]] void fail(const std::string& what) const;

private:
    void scan();
    void skipSpaceAndComments();
    void scanNumber();

    std::string_view text_;
    size_t pos_ = 0;
    std::string file_;
    int line_;
    Token token_;
};

}  // namespace brume::cal
