#include "scene/object_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "util/header.h"

namespace brume {

namespace {

using Word = SceneTokenizer::Word;

// Radiance's integer syntax (its isint): an optional sign and digits.
bool isInteger(std::string_view s) {
    if (s.starts_with('+') || s.starts_with('-')) s.remove_prefix(1);
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// Radiance's real syntax (its isflt): [sign] digits [. digits] [e [sign] digits], with at least one
// digit before the exponent. This rejects "nan", "inf" and hexadecimal.
bool isReal(std::string_view s) {
    if (s.starts_with('+') || s.starts_with('-')) s.remove_prefix(1);
    size_t digits = 0, i = 0;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) ++digits;
    if (i < s.size() && s[i] == '.')
        for (++i; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) ++digits;
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) return isInteger(s.substr(i + 1));
    return i == s.size();
}

// std::from_chars rejects the leading '+' that Radiance allows.
std::string_view withoutPlus(std::string_view s) { return s.starts_with('+') ? s.substr(1) : s; }

// How Radiance's xform lays out the reals of a type: some on the line of their count, then rows.
struct RealLayout {
    size_t onCountLine;
    size_t perRow;
    const char* rowStart;
    const char* format;
};

RealLayout layoutOf(std::string_view type, size_t count) {
    constexpr const char *kFull = "%18.12g", *kRounded = "%12.6g";
    constexpr std::string_view kRowsOfThree[] = {"polygon", "cone", "cup", "cylinder", "tube", "ring",
                                                 "brighttext", "colortext", "mixtext"};
    if (type == "interface") return {0, 4, "", kRounded};
    if (type == "mist" || type == "dielectric") return {count, 0, "", kRounded};
    if (type == "spotlight" && count == 7) return {4, 3, "\t", kFull};  // colour and angle, then direction
    for (std::string_view t : kRowsOfThree)
        if (type == t) return {0, 3, " ", kFull};
    return {count, 0, "", kFull};
}

std::string formatReal(const char* format, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string realsText(std::string_view type, const std::vector<double>& reals) {
    RealLayout layout = layoutOf(type, reals.size());
    std::string text = std::to_string(reals.size());
    for (size_t i = 0; i < reals.size(); ++i) {
        size_t row = i < layout.onCountLine ? 0 : i - layout.onCountLine;
        if (i < layout.onCountLine || row % layout.perRow != 0) text += ' ';
        else text += std::string("\n") + layout.rowStart;
        text += formatReal(layout.format, reals[i]);
    }
    return text + "\n";
}

}  // namespace

Word ObjectWords::word(std::string_view what) {
    std::optional<Word> next = tokens_.next();
    if (!next) throw Error(at(tokens_.line()), "unexpected end of file, expected " + std::string(what));
    return std::move(*next);
}

size_t ObjectWords::count(std::string_view kind) {
    Word w = word("number of " + std::string(kind) + " arguments");
    if (!isInteger(w.text) || w.text.starts_with('-'))
        throw Error(at(w.line), "bad number of " + std::string(kind) + " arguments '" + w.text + "'");
    return static_cast<size_t>(integer(w));
}

long ObjectWords::integer(const Word& w) const {
    if (!isInteger(w.text)) throw Error(at(w.line), "bad integer '" + w.text + "'");
    std::string_view s = withoutPlus(w.text);
    long value = 0;
    if (std::from_chars(s.data(), s.data() + s.size(), value).ec != std::errc())
        throw Error(at(w.line), "integer out of range '" + w.text + "'");
    return value;
}

double ObjectWords::real(const Word& w) const {
    if (!isReal(w.text)) throw Error(at(w.line), "bad real number '" + w.text + "'");
    std::string_view s = withoutPlus(w.text);
    double value = 0;
    if (std::from_chars(s.data(), s.data() + s.size(), value).ec != std::errc() || !std::isfinite(value))
        throw Error(at(w.line), "real number out of range '" + w.text + "'");
    return value;
}

void ObjectWords::readArguments(SceneObject& object) {
    for (size_t n = count("string"); n > 0; --n) object.strings.push_back(word("string argument").text);
    for (size_t n = count("integer"); n > 0; --n) object.integers.push_back(integer(word("integer argument")));
    for (size_t n = count("real"); n > 0; --n) object.reals.push_back(real(word("real argument")));
}

ObjectText ObjectWords::read() {
    ObjectText text;
    Word modifier = word("modifier");
    text.modifier = std::move(modifier.text);
    text.object.where = at(modifier.line);
    text.object.type = word("object type").text;
    text.object.name = word("identifier").text;
    if (text.object.type == "alias") text.object.strings.push_back(word("alias reference").text);
    else readArguments(text.object);
    return text;
}

std::string objectText(const ObjectText& o) {
    const SceneObject& object = o.object;
    std::string text = quotedWord(o.modifier) + " " + object.type + " " + quotedWord(object.name) + "\n";
    if (object.type == "alias") return text + "\t" + object.strings.at(0) + "\n";
    text += std::to_string(object.strings.size());
    for (const std::string& s : object.strings) text += " " + quotedWord(s);
    text += "\n" + std::to_string(object.integers.size());
    for (long i : object.integers) text += " " + std::to_string(i);
    return text + "\n" + realsText(object.type, object.reals);
}

}  // namespace brume
