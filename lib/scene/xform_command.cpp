#include "scene/xform_command.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <span>

namespace brume {

namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)); }

// The lines of an argument file; a backslash before a newline continues the line (as Radiance's fgetline).
std::vector<std::string> readLines(std::istream& in) {
    std::vector<std::string> lines;
    std::string line;
    for (int c; (c = in.get()) != EOF;) {
        if (c == '\r' && in.peek() == '\n') continue;
        if (c == '\n' && !line.ends_with('\\')) {
            lines.push_back(std::move(line));
            line.clear();
        } else {
            line += static_cast<char>(c);
        }
    }
    if (!line.empty()) lines.push_back(std::move(line));
    return lines;
}

bool passedOn(const std::string& line) { return line.empty() || line[0] == '#'; }

// The words of an argument file line, which may be written as a command ("!xform -t 1 0 0"). Quotes group
// words; a backslash takes the next character as it is, and with a newline continues the line.
std::vector<std::string> lineWords(std::string_view line) {
    if (line.starts_with('!')) line.remove_prefix(1);
    if (line.starts_with("xform ")) line.remove_prefix(6);
    std::vector<std::string> words;
    for (size_t i = 0, n = line.size();;) {
        while (i < n && isSpace(line[i])) ++i;
        char quote = 0;
        if (i < n && (line[i] == '"' || line[i] == '\'')) quote = line[i++];
        if (i >= n) return words;
        if (line[i] == '\\' && i + 1 < n && line[++i] == '\n') continue;
        size_t end = quote ? i : i + 1;
        while (end < n && (quote ? line[end] != quote : !isSpace(line[end]))) ++end;
        words.emplace_back(line.substr(i, end - i));
        i = end + (quote && end < n ? 1 : 0);
    }
}

}  // namespace

void XformExpansion::forEachRun(const std::vector<std::string>& argv, const Visit& visit) {
    for (size_t a = 1; a < argv.size(); ++a)
        if (argv[a] == "-f") return argumentFile(argv, a, visit);
    for (size_t a = 1; a < argv.size(); ++a)
        if (argv[a] == "-a") return array(argv, a, visit);
    visit({argv, {}});
}

const std::vector<std::string>& XformExpansion::lines(const std::string& file) {
    if (auto it = files_.find(file); it != files_.end()) return it->second;
    if (file == "-") return files_[file] = readLines(std::cin);
    std::ifstream in(file);
    if (!in) throw Error(SourceLocation{file}, "cannot open argument file");
    std::vector<std::string> lines = readLines(in);
    if (std::all_of(lines.begin(), lines.end(), passedOn)) throw Error(SourceLocation{file}, "empty argument file");
    return files_[file] = std::move(lines);
}

// Each line of the file makes a run, its words in place of "-f file", named "-n i<k>" (or with ".<k>"
// added to the first -n name) as Radiance does; comments and blank lines go to the output.
void XformExpansion::argumentFile(const std::vector<std::string>& argv, size_t at, const Visit& visit) {
    if (at + 1 >= argv.size() || (argv[at + 1].size() > 1 && argv[at + 1][0] == '-'))
        throw Error("missing file for -f option");
    const std::string& file = argv[at + 1];
    if (!expanding_.insert(file).second) throw Error(SourceLocation{file}, "argument file names itself with -f");
    size_t k = 0;
    for (const std::string& line : lines(file)) {
        if (passedOn(line)) {
            visit({{}, line});
            continue;
        }
        std::vector<std::string> args(argv.begin(), argv.begin() + at);
        for (std::string& word : lineWords(line)) args.push_back(std::move(word));
        args.insert(args.end(), argv.begin() + at + 2, argv.end());
        size_t named = 0;  // the value of the first -n
        for (size_t i = 2; i < args.size() && !named; ++i)
            if (args[i - 1] == "-n") named = i;
        if (named) args[named] += "." + std::to_string(k);
        else args.insert(args.begin() + 1, {"-n", "i" + std::to_string(k)});
        forEachRun(args, visit);
        ++k;
    }
    expanding_.erase(file);
}

// "-a n" becomes "-i k" for k = 0 .. n-1, each copy named "-n a<k>" (or with ".<k>" added to the -n names).
void XformExpansion::array(const std::vector<std::string>& argv, size_t at, const Visit& visit) {
    long n = at + 1 < argv.size() ? std::atol(argv[at + 1].c_str()) : 0;  // atoi, as Radiance
    if (n <= 0) throw Error("missing count for -a option");
    std::vector<size_t> names;
    for (size_t i = 1; i < argv.size(); ++i)
        if (argv[i - 1] == "-n") names.push_back(i);
    for (long k = 0; k < n; ++k) {
        std::vector<std::string> args = argv;
        std::string id = names.empty() ? "a" + std::to_string(k) : argv[names.back()] + "." + std::to_string(k);
        for (size_t i : names) args[i] = id;
        args[at] = "-i", args[at + 1] = std::to_string(k);
        if (names.empty()) args.insert(args.begin() + 1, {"-n", id});
        forEachRun(args, visit);
    }
}

XformCommand parseXformCommand(const std::vector<std::string>& args) {
    XformCommand c;
    ObjectTransform& o = c.transform.objects;
    size_t a = 1;
    for (; a < args.size(); ++a) {
        const std::string& w = args[a];
        bool valued = a + 1 < args.size();
        if (w == "-m" && valued) {
            if (o.modifier.empty()) o.modifier = args[a + 1];  // the first -m wins
            ++a;
        } else if (w == "-n" && valued) o.prefix += (o.prefix.empty() ? "" : ".") + args[++a];
        else if (w == "-c" || w == "-e") c.transform.expandCommands = w == "-e";
        else if (w == "-I") o.invert = !o.invert;
        else break;
    }
    size_t first = a;  // of the transform
    ParsedTransform t = parseTransform(std::span(args).subspan(a));
    a += t.used;
    if (a < args.size() && args[a].starts_with('-')) throw Error("command line error at '" + args[a] + "'");
    o.transform = t.transform;
    o.words.assign(args.begin() + first, args.begin() + a);
    c.files.assign(args.begin() + a, args.end());
    c.header = "#";
    for (size_t i = 0; i < a; ++i) c.header += " " + args[i];
    // Commands passed on (-c) are transformed when run, by the same options less -c.
    if (a > 1) c.transform.commandPipe = " | " + args[0] + " -e";
    for (size_t i = 1; i < a; ++i)
        if (i >= first || args[i] != "-c") c.transform.commandPipe += " " + args[i];
    return c;
}

}  // namespace brume
