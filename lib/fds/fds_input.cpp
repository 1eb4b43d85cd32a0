#include "fds/fds_input.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "util/error.h"

namespace brume {

std::string upperCase(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

namespace {

// A cursor over the file's text that knows its line.
struct Text {
    const std::string& s;
    const std::string& file;
    size_t at = 0;
    int line = 1;

    bool done() const { return at >= s.size(); }
    char peek() const { return s[at]; }
    char next() {
        char c = s[at++];
        if (c == '\n') ++line;
        return c;
    }
    std::string here() const { return file + ":" + std::to_string(line); }
    void skipSpace() {
        while (!done() && (std::isspace(static_cast<unsigned char>(peek())) || peek() == ',')) next();
    }
    std::string word() {
        std::string w;
        while (!done() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_')) w += next();
        return w;
    }
};

// One value: a quoted string (its quotes taken off), or a bare token up to a separator.
std::string value(Text& t) {
    if (t.peek() == '\'' || t.peek() == '"') {
        const char quote = t.next();
        const std::string start = t.here();
        std::string v;
        while (!t.done() && t.peek() != quote) v += t.next();
        if (t.done()) throw Error(start + ": a string not closed by " + std::string(1, quote));
        t.next();
        return v;
    }
    std::string v;
    while (!t.done() && !std::isspace(static_cast<unsigned char>(t.peek())) && t.peek() != ',' && t.peek() != '/')
        v += t.next();
    return v;
}

// Whether the text at the cursor starts a parameter: a name, an optional (…) index, then '='.
bool atParameter(const Text& t) {
    size_t i = t.at;
    while (i < t.s.size() && (std::isalnum(static_cast<unsigned char>(t.s[i])) || t.s[i] == '_')) ++i;
    if (i == t.at || std::isdigit(static_cast<unsigned char>(t.s[t.at]))) return false;
    if (i < t.s.size() && t.s[i] == '(') i = t.s.find(')', i) == std::string::npos ? i : t.s.find(')', i) + 1;
    while (i < t.s.size() && std::isspace(static_cast<unsigned char>(t.s[i]))) ++i;
    return i < t.s.size() && t.s[i] == '=';
}

FdsGroup group(Text& t) {
    FdsGroup g;
    g.where = t.here();
    t.next();  // '&'
    g.name = upperCase(t.word());
    if (g.name.empty()) throw Error(g.where + ": '&' without a group name");
    for (;;) {
        t.skipSpace();
        if (t.done()) throw Error(g.where + ": &" + g.name + " is not closed by '/'");
        if (t.peek() == '/') {
            t.next();
            return g;
        }
        if (!atParameter(t)) throw Error(t.here() + ": &" + g.name + ": expected a parameter (NAME=value), not '" +
                                          t.s.substr(t.at, std::min<size_t>(20, t.s.size() - t.at)) + "'");
        std::string key = upperCase(t.word());
        while (!t.done() && t.peek() != '=') key += t.next();  // an index, "(1:5)", kept with its name
        t.skipSpace();
        t.next();  // '='
        std::vector<std::string>& values = g.values[key];
        values.clear();
        for (t.skipSpace(); !t.done() && t.peek() != '/' && !atParameter(t); t.skipSpace()) values.push_back(value(t));
        if (values.empty()) throw Error(t.here() + ": &" + g.name + " " + key + " has no value");
    }
}

}  // namespace

const std::vector<std::string>* FdsGroup::find(const std::string& key) const {
    auto it = values.find(key);
    return it == values.end() ? nullptr : &it->second;
}

std::optional<std::string> FdsGroup::text(const std::string& key) const {
    const std::vector<std::string>* v = find(key);
    if (!v) return std::nullopt;
    return v->front();
}

std::optional<std::vector<double>> FdsGroup::numbers(const std::string& key, size_t n) const {
    const std::vector<std::string>* v = find(key);
    if (!v) return std::nullopt;
    if (v->size() != n)
        throw Error(where + ": &" + name + " " + key + ": expected " + std::to_string(n) + " numbers, found " +
                    std::to_string(v->size()));
    std::vector<double> out;
    for (const std::string& w : *v) {
        double x = 0;
        std::string d = w;
        for (char& c : d)
            if (c == 'd' || c == 'D') c = 'e';  // Fortran's double-precision exponent
        auto [end, ec] = std::from_chars(d.data(), d.data() + d.size(), x);
        if (ec != std::errc() || end != d.data() + d.size() || !std::isfinite(x))
            throw Error(where + ": &" + name + " " + key + ": '" + w + "' is not a number");
        out.push_back(x);
    }
    return out;
}

std::vector<FdsGroup> readFdsInput(std::istream& in, const std::string& file) {
    std::ostringstream all;
    all << in.rdbuf();
    if (in.bad()) throw Error(file + ": cannot be read");
    const std::string s = all.str();
    Text t{s, file};
    std::vector<FdsGroup> groups;
    bool lineStart = true;  // a group starts where '&' is a line's first word; anything else is comment
    while (!t.done()) {
        const char c = t.peek();
        if (c == '&' && lineStart) {
            groups.push_back(group(t));
            lineStart = false;
            continue;
        }
        t.next();
        if (c == '\n') lineStart = true;
        else if (!std::isspace(static_cast<unsigned char>(c))) lineStart = false;
    }
    return groups;
}

}  // namespace brume
