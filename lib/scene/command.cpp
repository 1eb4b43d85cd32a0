#include "scene/command.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "util/error.h"

namespace brume {

namespace {

std::string describeStatus(int status) {
    if (status == -1) return "could not be waited for";
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
    return "failed";
}

// Brume's own programs first on PATH: "!xform ..." and "!gensky ..." in a scene written for Radiance then
// run the versions installed beside the running program. PATH is set once and inherited by the commands.
void putOwnDirectoryFirstOnPath() {
    static std::once_flag once;
    std::call_once(once, [] {
        std::error_code ec;
        std::string own = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path().string();
        const char* path = std::getenv("PATH");
        std::string rest = path ? path : "/usr/local/bin:/usr/bin:/bin";  // the shell's default when unset
        if (!ec && !own.empty() && rest != own && !rest.starts_with(own + ":"))
            setenv("PATH", (own + ":" + rest).c_str(), 1);
    });
}

}  // namespace

std::string commandOutput(const std::string& command) {
    putOwnDirectoryFirstOnPath();
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
