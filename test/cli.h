// Running Brume's programs from end-to-end tests: a shell command line, what it wrote, its exit status.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.h"

namespace brume_test {

struct Output {
    std::string out, err;
    int status;
};

inline std::string slurp(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

// Runs the shell command `line`, its standard output and error captured through files in `scratch`.
inline Output runCaptured(const std::string& line, const std::filesystem::path& scratch) {
    std::string cmd = line + " > '" + (scratch / "out").string() + "' 2> '" + (scratch / "err").string() + "'";
    int status = std::system(cmd.c_str());
    return {slurp(scratch / "out"), slurp(scratch / "err"), WEXITSTATUS(status)};
}

// Runs the shell commands `lines` in `scratch`, Brume's programs first on the PATH; all their output is
// captured.
inline Output runBrume(const std::string& lines, const std::filesystem::path& scratch) {
    return runCaptured("cd '" + scratch.string() + "' && PATH='" + std::string(BRUME_BIN_DIR) + "':\"$PATH\" && {\n" +
                           lines + "\n}",
                       scratch);
}

// A room lit by a sphere lamp: a floor, one wall and a ceiling of grey plastic.
inline const char* const kLampRoom =
    "void light lum 0 0 3 100 100 100\n"
    "lum sphere bulb 0 0 4 0 0 2 0.1\n"
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n"
    "grey polygon wall 0 0 12 -5 -5 0 -5 5 0 -5 5 4 -5 -5 4\n"
    "grey polygon ceiling 0 0 12 -5 -5 4 -5 5 4 5 5 4 5 -5 4\n";

// The record count in mkcache's report "mkcache: file: N records (...)", or -1.
inline long reportedRecords(const std::string& err) {
    size_t at = err.find(" records (");
    if (at == std::string::npos) return -1;
    size_t start = err.rfind(' ', at - 1) + 1;
    return std::stol(err.substr(start, at - start));
}

}  // namespace brume_test
