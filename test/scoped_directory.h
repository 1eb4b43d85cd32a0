// Running part of a test in another directory: normal octrees name their scene files, and instances their
// octrees, relative to the directory they are read in.
#pragma once
#include <filesystem>

namespace brume_test {

// The current directory is `dir` until this ends, then what it was (also when the test fails on the way).
class ScopedDirectory {
public:
    explicit ScopedDirectory(const std::filesystem::path& dir) : old_(std::filesystem::current_path()) {
        std::filesystem::current_path(dir);
    }
    ~ScopedDirectory() {
        std::error_code ignored;
        std::filesystem::current_path(old_, ignored);
    }
    ScopedDirectory(const ScopedDirectory&) = delete;
    ScopedDirectory& operator=(const ScopedDirectory&) = delete;

private:
    std::filesystem::path old_;
};

}  // namespace brume_test
