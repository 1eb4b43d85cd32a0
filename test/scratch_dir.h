// Scratch directories of a test process, removed with all they hold when it ends (each test is a process
// of its own under ctest, so a directory named by pid is the test's alone).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace brume_test {

class ScratchDirs {
public:
    ~ScratchDirs() {
        std::error_code ignored;
        for (const std::filesystem::path& d : dirs_) std::filesystem::remove_all(d, ignored);
    }
    const std::filesystem::path& add(std::filesystem::path dir) {
        std::filesystem::create_directories(dir);
        for (const std::filesystem::path& d : dirs_)
            if (d == dir) return d;
        return dirs_.emplace_back(std::move(dir));
    }

private:
    std::vector<std::filesystem::path> dirs_;
};

// The scratch directory of this test process for `tag`.
inline std::filesystem::path scratchDir(const std::string& tag) {
    static ScratchDirs dirs;
    return dirs.add(std::filesystem::temp_directory_path() / ("brume_" + tag + "_" + std::to_string(::getpid())));
}

}  // namespace brume_test
