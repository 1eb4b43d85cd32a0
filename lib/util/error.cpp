#include "util/error.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <set>

namespace brume {

namespace {
std::string gProgram = "brume";
bool gWarnings = true;
std::mutex gWarnMutex;
}  // namespace

std::string SourceLocation::str() const {
    return line > 0 ? file + ":" + std::to_string(line) : file;
}

Error::Error(const SourceLocation& where, const std::string& what) : std::runtime_error(where.str() + ": " + what) {}

int runReportingErrors(const std::function<int()>& run) {
    try {
        int status = run();
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) throw std::runtime_error("write error");
        return status;
    } catch (const Error& e) {
        std::fflush(stdout);  // what was written before the error is kept
        std::cerr << gProgram << ": " << e.what() << '\n';
        if (auto* u = dynamic_cast<const UsageError*>(&e)) std::cerr << u->usage();
        return 1;
    } catch (const std::exception& e) {
        std::cerr << gProgram << ": system - " << e.what() << '\n';
        return 2;
    }
}

void setProgramName(const std::string& name) {
    auto slash = name.find_last_of('/');
    gProgram = slash == std::string::npos ? name : name.substr(slash + 1);
}

const std::string& programName() { return gProgram; }

void setWarningsEnabled(bool on) { gWarnings = on; }

void warn(const std::string& what) {
    if (!gWarnings) return;
    std::lock_guard lock(gWarnMutex);
    std::cerr << gProgram << ": warning - " << what << '\n';
}

void warnOnce(const std::string& what) {
    static std::set<std::string> said;
    {
        std::lock_guard lock(gWarnMutex);
        if (!said.insert(what).second) return;
    }
    warn(what);
}

std::string shownBytes(std::string_view text, size_t longest) {
    std::string out;
    for (size_t i = 0; i < std::min(text.size(), longest); ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        out += std::isprint(c) ? std::string(1, char(c)) : std::string(hex);
    }
    return text.size() > longest ? out + "..." : out;
}

}  // namespace brume
