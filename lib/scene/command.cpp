#include "scene/command.h"

#include <sys/wait.h>

#include <cstdio>

#include "util/error.h"

namespace brume {

namespace {

std::string describeStatus(int status) {
    if (status == -1) return "could not be waited for";
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
    return "failed";
}

}  // namespace

std::string commandOutput(const std::string& command) {
    std::fflush(nullptr);  // so the command's output cannot overtake ours
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw Error("!" + command + ": cannot run command");
    std::string output;
    char buffer[65536];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
    int status = pclose(pipe);
    if (status != 0) throw Error("!" + command + ": command " + describeStatus(status));
    return output;
}

}  // namespace brume
