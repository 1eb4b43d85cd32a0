// For the medium's unit tests: grids of known content built in memory, and the real grids in ../shared/data.
#pragma once
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <filesystem>
#include <string>

#include "medium/density_grid.h"
#include "medium/openvdb/openvdb_grid.h"
#include "util/error.h"

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

// `grid` made safe as a density, as read from a file (its warnings printed).
inline DensityGrid densityOf(openvdb::FloatGrid::Ptr grid, const std::string& name = "test grid") {
    std::vector<std::string> warnings;
    auto voxels = std::make_shared<OpenVdbGrid>(std::move(grid), name, warnings);
    for (const std::string& w : warnings) warn(w);
    return DensityGrid(std::move(voxels));
}
// The OpenVDB tree behind a grid.
inline const openvdb::FloatGrid& vdbOf(const DensityGrid& grid) {
    return dynamic_cast<const OpenVdbGrid&>(grid.voxels()).grid();
}

// Writes `grid` as grid `name` of the .vdb file `path`.
inline void writeGrid(const std::filesystem::path& path, openvdb::FloatGrid::Ptr grid, const std::string& name = "density") {
    grid->setName(name);
    openvdb::io::File(path.string()).write({grid});
}

}  // namespace brume::medium::testing
