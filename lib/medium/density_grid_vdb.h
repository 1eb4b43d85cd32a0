// The OpenVDB grid behind a DensityGrid, for lib/medium's .cpp files and tests: OpenVDB's headers are heavy,
// so nothing else includes this.
#pragma once
#include <openvdb/openvdb.h>

#include "medium/density_grid.h"

namespace brume {

struct DensityGrid::Voxels {
    // Takes `grid` as a density (see DensityGrid): refuses a level set, cleans hostile and inactive values.
    // `source` names it in messages: `file: grid "name"`.
    Voxels(openvdb::FloatGrid::Ptr grid, std::string source);

    openvdb::FloatGrid::ConstPtr grid;
    std::string source;
    openvdb::CoordBBox active;  // index box of the active voxels and tiles; empty for an empty grid
    float max = 0;
};

}  // namespace brume
