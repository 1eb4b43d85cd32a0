// Splitting .rad text into Radiance's words, tracking line numbers for messages.
#pragma once
#include <optional>
#include <streambuf>
#include <string>
#include <utility>

namespace brume {

// A word is a run of non-space characters; '...' or "..." quotes (which may start mid-word and are
// removed) let it hold spaces, as in Radiance's fgetword.
class SceneTokenizer {
public:
    struct Word {
        std::string text;
        int line;  // where the word starts
    };

    // `name` is the file name used in error messages.
    SceneTokenizer(std::streambuf* in, std::string name) : in_(in), name_(std::move(name)) {}

    // Skips white space; returns the next character without consuming it, or EOF.
    int peek();
    // The next word, or nothing at the end of the input. Throws brume::Error on an unterminated quote.
    std::optional<Word> next();
    // The rest of the current line, without its newline. With `continued`, a newline right after a
    // backslash does not end the line (as in Radiance's !command lines) and is kept.
    std::string restOfLine(bool continued);
    int line() const { return line_; }

private:
    int get();

    std::streambuf* in_;
    std::string name_;
    int line_ = 1;
};

}  // namespace brume
