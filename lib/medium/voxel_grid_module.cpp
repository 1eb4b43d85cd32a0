#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <vector>

#include "medium/voxel_grid.h"
#include "util/error.h"

namespace brume {

namespace {

using ReadGrid = VoxelGrid* (*)(const std::string& path, const std::string& name, std::string& error,
                                std::vector<std::string>& warnings);
constexpr const char* kModule = "libbrume_openvdb.so";

// The module beside the running program (the build's bin/), or in lib/brume beside its bin/ (installed);
// null with `why` set when neither loads.
ReadGrid loadModule(std::string& why) {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) {
        why = "cannot find the running program (/proc/self/exe): " + ec.message();
        return nullptr;
    }
    for (const std::filesystem::path& place :
         {program.parent_path() / kModule, program.parent_path().parent_path() / "lib" / "brume" / kModule}) {
        if (!std::filesystem::exists(place)) continue;
        void* module = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            why = dlerror();
            return nullptr;
        }
        if (auto read = reinterpret_cast<ReadGrid>(dlsym(module, "brumeReadOpenVdb"))) return read;
        why = place.string() + " has no brumeReadOpenVdb";
        return nullptr;
    }
    why = std::string(kModule) + " is neither beside " + program.string() + " nor in ../lib/brume";
    return nullptr;
}

}  // namespace

std::shared_ptr<const VoxelGrid> readVoxelGrid(const std::string& path, const std::string& name) {
    static std::once_flag once;
    static ReadGrid read = nullptr;
    static std::string why;
    std::call_once(once, [] { read = loadModule(why); });
    if (!read) throw Error(path + ": cannot read OpenVDB grids: " + why);
    std::string error;
    std::vector<std::string> warnings;
    VoxelGrid* grid = read(path, name, error, warnings);
    for (const std::string& w : warnings) warn(w);
    if (!grid) throw Error(error);
    return std::shared_ptr<const VoxelGrid>(grid);
}

}  // namespace brume
