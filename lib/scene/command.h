// Running the shell commands of "!command" lines and file names.
#pragma once
#include <string>

namespace brume {

// The standard output of `command`, run by /bin/sh with the running program's directory first on PATH (so
// that Brume's xform, gensky ... are the ones found). Throws brume::Error ("!command: ...") if it cannot
// be run or does not exit with status 0.
std::string commandOutput(const std::string& command);

}  // namespace brume
