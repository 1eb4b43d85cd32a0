// For the medium's unit tests: grids of known content built in memory, and the real grids in ../shared/data.
#pragma once
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <filesystem>
#include <string>

#include "medium/density_grid_vdb.h"

namespace brume::medium::testing {

// The real grid ../shared/data/vdb/<name>, or "" when the shared data is absent (the caller skips).
inline std::string sharedGrid(const std::string& name) {
    const std::filesystem::path path = std::filesystem::path(BRUME_SHARED_DATA) / "vdb" / name;
    return std::filesystem::exists(path) ? path.string() : "";
}
#define BRUME_SHARED_GRID_OR_SKIP(var, name)                                        \
    const std::string var = ::brume::medium::testing::sharedGrid(name);             \
    if (var.empty()) GTEST_SKIP() << "no " << name << " in " << BRUME_SHARED_DATA

// Voxels lo..hi (index, inclusive) holding `value`, active, in a grid of zero background.
inline openvdb::FloatGrid::Ptr boxGrid(openvdb::Coord lo, openvdb::Coord hi, float value, double voxelSize = 1.0) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->tree().fill(openvdb::CoordBBox(lo, hi), value, /*active=*/true);
    return grid;
}

inline DensityGrid densityOf(openvdb::FloatGrid::Ptr grid, const std::string& name = "test grid") {
    return DensityGrid(std::make_shared<DensityGrid::Voxels>(std::move(grid), name));
}

// Writes `grid` as grid `name` of the .vdb file `path`.
inline void writeGrid(const std::filesystem::path& path, openvdb::FloatGrid::Ptr grid, const std::string& name = "density") {
    grid->setName(name);
    openvdb::io::File(path.string()).write({grid});
}

}  // namespace brume::medium::testing
