// The entry point of libbrume_openvdb.so, which lib/medium/voxel_grid_module.cpp loads with dlopen the first
// time a grid is read.
#include <exception>

#include "medium/openvdb/openvdb_grid.h"

// Reads grid `name` of `path`: the grid, or null with `error` set; `warnings` receives what was cleaned.
extern "C" brume::VoxelGrid* brumeReadOpenVdb(const std::string& path, const std::string& name, std::string& error,
                                               std::vector<std::string>& warnings) {
    try {
        return new brume::OpenVdbGrid(brume::readFloatGrid(path, name), path + ": grid \"" + name + "\"", warnings);
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
}
