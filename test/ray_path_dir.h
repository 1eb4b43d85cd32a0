// A scratch directory that is all of RAYPATH for the life of the object, for tests of file lookups.
#pragma once
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace brume {

class RayPathDir {
public:
    RayPathDir() : dir_(std::filesystem::temp_directory_path() / ("brume_raypath_" + std::to_string(getpid()))) {
        std::filesystem::create_directories(dir_);
        if (const char* old = std::getenv("RAYPATH")) old_ = old;
        setenv("RAYPATH", dir_.c_str(), 1);
    }
    ~RayPathDir() {
        old_ ? setenv("RAYPATH", old_->c_str(), 1) : unsetenv("RAYPATH");
        std::filesystem::remove_all(dir_);
    }
    RayPathDir(const RayPathDir&) = delete;
    RayPathDir& operator=(const RayPathDir&) = delete;

    void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
    // Where to write files of other kinds.
    const std::filesystem::path& path() const { return dir_; }

private:
    std::filesystem::path dir_;
    std::optional<std::string> old_;
};

}  // namespace brume
