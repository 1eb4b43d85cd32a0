// Errors and warnings in Radiance's style: "program: file:line: what is wrong" on stderr.
#pragma once
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace brume {

// Where a piece of scene text or input came from; line 0 means "the whole file" or unknown.
struct SourceLocation {
    std::string file;
    int line = 0;
    std::string str() const;  // "file:line" (or "file" when line is 0)
};

// A user-facing error: bad scene, bad option, bad input. The message never includes the program name;
// the tool's main() prefixes it when it reports the error and exits non-zero.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
    Error(const SourceLocation& where, const std::string& what);
};

// Untrusted text (bytes read from a file or a stream) as a message may show it: bytes that do not print as
// \xNN, cut after `longest` of them with "..." (binary input would otherwise write to the terminal).
std::string shownBytes(std::string_view text, size_t longest);

// A mistake in the command line: reported as an Error, followed by the program's usage.
class UsageError : public Error {
public:
    UsageError(const std::string& what, std::string usage) : Error(what), usage_(std::move(usage)) {}
    const std::string& usage() const { return usage_; }

private:
    std::string usage_;
};

// The body of a tool's main: returns what `run` returns once the standard output is flushed; reports an
// Error as "program: what" (and the usage after a UsageError) with status 1, any other exception (a
// failed write among them) as "program: system - what" with status 2.
int runReportingErrors(const std::function<int()>& run);

// The program name printed before every message (set once by each tool's main).
void setProgramName(const std::string& name);
const std::string& programName();

// Warnings go to stderr as "program: warning - what", unless disabled with -w-.
void setWarningsEnabled(bool on);
void warn(const std::string& what);
// Same, but printed only the first time this exact message is given.
void warnOnce(const std::string& what);

}  // namespace brume
