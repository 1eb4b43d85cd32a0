#include "util/options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace brume {

void OptionTable::add(const std::string& name, int count, const std::string& help, Apply apply,
                      std::function<std::string()> current) {
    options_.push_back({name, Kind::Separate, count, help, std::move(apply), std::move(current)});
}

void OptionTable::remove(const std::string& name) {
    std::erase_if(options_, [&](const Option& o) { return o.name == name; });
}

void addIntOption(OptionTable& t, const std::string& name, int& v, const std::string& help) {
    t.add(name, 1, help, [&v, name](const auto& a) { v = toInt(name, a[0]); }, [&v] { return std::to_string(v); });
}

void addRealOption(OptionTable& t, const std::string& name, double& v, const std::string& help) {
    t.add(name, 1, help, [&v, name](const auto& a) { v = toReal(name, a[0]); }, [&v] { return formatReal(v); });
}

std::string formatReal(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%f", v);
    return buf;
}

std::string formatShort(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

void OptionTable::addUnsupported(const std::string& name, int count, const std::string& help) {
    add(name, count, help + " (not supported yet)",
        [name](const std::vector<std::string>&) { throw Error("option " + name + " is not supported by Brume yet"); });
}

void OptionTable::addBool(const std::string& name, bool& value, const std::string& help) {
    bool* v = &value;
    options_.push_back({name, Kind::Bool, 0, help,
                        [v, name](const std::vector<std::string>& a) {
                            const std::string& s = a[0];
                            if (s.empty()) *v = !*v;
                            else if (s == "+" || s == "1" || s == "y" || s == "Y" || s == "t" || s == "T") *v = true;
                            else if (s == "-" || s == "0" || s == "n" || s == "N" || s == "f" || s == "F") *v = false;
                            else throw Error("bad boolean '" + s + "' for option " + name);
                        },
                        [v] { return std::string(*v ? "+" : "-"); }});
}

void OptionTable::addAttached(const std::string& name, const std::string& help,
                              std::function<void(const std::string&)> apply, std::function<std::string()> current) {
    options_.push_back({name, Kind::Attached, 0, help,
                        [apply = std::move(apply)](const std::vector<std::string>& a) { apply(a[0]); },
                        std::move(current)});
}

// The option this word names: an exact name for options with separate arguments, the longest matching
// prefix for booleans and attached values.
const OptionTable::Option* OptionTable::find(const std::string& word) const {
    const Option* best = nullptr;
    for (const Option& o : options_) {
        bool match = o.kind == Kind::Separate ? word == o.name : word.compare(0, o.name.size(), o.name) == 0;
        if (match && (!best || o.name.size() > best->name.size())) best = &o;
    }
    if (best && best->kind == Kind::Bool && word.size() > best->name.size() + 1) return nullptr;
    return best;
}

size_t OptionTable::parse(std::vector<std::string>& args) const {
    expandResponseFiles(args);
    size_t i = 0;
    // Radiance's sky generators also take options that start with '+' (gensky +s); those must be declared.
    while (i < args.size() && args[i].size() > 1 && (args[i][0] == '-' || (args[i][0] == '+' && find(args[i])))) {
        const std::string& word = args[i];
        const Option* o = find(word);
        if (!o) throw Error("unknown option " + word);
        if (o->kind == Kind::Separate) {
            if (i + o->count >= args.size()) throw Error("missing argument for option " + word);
            o->apply({args.begin() + i + 1, args.begin() + i + 1 + o->count});
            i += 1 + o->count;
        } else {
            o->apply({word.substr(o->name.size())});
            ++i;
        }
    }
    return i;
}

std::string OptionTable::usage() const {
    std::ostringstream out;
    for (const Option& o : options_) {
        std::string syntax = o.name;
        if (o.kind == Kind::Bool) syntax += "[+-]";
        else if (o.kind == Kind::Attached) syntax += "...";
        else
            for (int k = 0; k < o.count; ++k) syntax += " v";
        out << "  " << syntax << std::string(syntax.size() < 16 ? 16 - syntax.size() : 1, ' ') << o.help << '\n';
    }
    return out.str();
}

void OptionTable::changeNothing(const std::vector<std::string>& names) {
    for (Option& o : options_)
        if (std::find(names.begin(), names.end(), o.name) != names.end() && o.changesValues) {
            o.changesValues = false;
            o.help += " (accepted; changes nothing in Brume)";
        }
}

// "-ab 5", "-I+", "-faa"; empty for an option that is not set.
std::string OptionTable::setting(const Option& o) const {
    std::string value = o.current();
    if (value.empty() && o.kind == Kind::Separate) return "";
    return o.name + (o.kind == Kind::Separate ? " " : "") + value;
}

std::string OptionTable::defaults() const {
    std::ostringstream out;
    for (const Option& o : options_) {
        if (!o.current) continue;
        std::string line = setting(o);
        if (line.empty()) line = "#" + o.name + " (not set)";
        out << line << std::string(line.size() < 32 ? 32 - line.size() : 1, ' ') << "# " << o.help << '\n';
    }
    return out.str();
}

std::vector<std::string> OptionTable::valueOptions() const {
    std::vector<std::string> out;
    for (const Option& o : options_)
        if (o.current && o.changesValues)
            if (std::string s = setting(o); !s.empty()) out.push_back(s);
    return out;
}

int toInt(const std::string& option, const std::string& text) {
    try {
        size_t used;
        long v = std::stol(text, &used);
        if (used == text.size() && v >= INT32_MIN && v <= INT32_MAX) return static_cast<int>(v);
    } catch (const std::exception&) {
    }
    throw Error("bad value '" + text + "' for option " + option);
}

double toReal(const std::string& option, const std::string& text) {
    try {
        size_t used;
        double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw Error("bad value '" + text + "' for option " + option);
}

namespace {

std::vector<std::string> wordsOfFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open option file '" + path + "'");
    std::vector<std::string> words;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string w;
        while (ls >> w) {
            if (w[0] == '#') break;
            if (w.front() == '"' || w.front() == '\'') {
                char q = w.front();
                std::string rest;
                while (w.size() < 2 || w.back() != q) {
                    if (!(ls >> rest)) throw Error(path + ": unmatched quote");
                    w += ' ' + rest;
                }
                w = w.substr(1, w.size() - 2);
            }
            words.push_back(w);
        }
    }
    return words;
}

}  // namespace

std::vector<std::string> splitWords(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

// @file and $VARIABLE words are replaced by the words they hold, repeatedly, as Radiance's expandarg.
void expandResponseFiles(std::vector<std::string>& args) {
    int expansions = 0;
    for (size_t i = 0; i < args.size();) {
        const std::string& a = args[i];
        if (a.size() < 2 || (a[0] != '@' && a[0] != '$')) {
            ++i;
            continue;
        }
        if (++expansions > 1000) throw Error("too many @file or $VARIABLE expansions at '" + a + "'");
        std::vector<std::string> words;
        if (a[0] == '@') {
            words = wordsOfFile(a.substr(1));
        } else {
            const char* value = std::getenv(a.c_str() + 1);
            if (!value) throw Error("cannot expand '" + a + "': no such environment variable");
            words = splitWords(value);
        }
        args.erase(args.begin() + i);
        args.insert(args.begin() + i, words.begin(), words.end());
    }
}

std::vector<std::string> operandsAfterOptions(const OptionTable& table, int argc, char** argv, const std::string& usage) {
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t first;
    try {
        first = table.parse(args);
    } catch (const Error& e) {
        throw UsageError(e.what(), usage + table.usage());
    }
    return {args.begin() + first, args.end()};
}

}  // namespace brume
