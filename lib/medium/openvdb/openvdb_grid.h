// The OpenVDB grid behind a VoxelGrid, compiled into the module libbrume_openvdb.so (and into the medium's
// tests, which build grids in memory): nothing else includes OpenVDB's (heavy) headers.
#pragma once
#include <openvdb/openvdb.h>

#include <string>
#include <vector>

#include "medium/dense_voxels.h"
#include "medium/voxel_grid.h"

namespace brume {

class OpenVdbGrid final : public VoxelGrid {
public:
    // Whether the active voxels' box is also copied into one array (DenseVoxels), which lookups then read:
    // when it takes at most twice the tree's memory (a box mostly full: OpenVDB's smoke1, a third full, is).
    enum class Copy { WhenSmall, Never };

    // Takes `grid` as a density (see DensityGrid): refuses a level set or a frustum transform (Error), cleans
    // hostile and inactive values, and says so in `warnings`. `source` names it in messages:
    // `file: grid "name"`.
    OpenVdbGrid(openvdb::FloatGrid::Ptr grid, std::string source, std::vector<std::string>& warnings,
                Copy copy = Copy::WhenSmall);

    Bounds3 bounds() const override;
    double density(const dvec3& p) const override;
    double maxDensity() const override { return max_; }
    std::uint64_t activeVoxelCount() const override { return grid_->activeVoxelCount(); }
    std::uint64_t memoryBytes() const override { return grid_->memUsage() + dense_.memoryBytes(); }
    glm::dmat4 worldFromIndex() const override;
    bool sameTransform(const VoxelGrid& other) const override;
    std::optional<IndexBox> activeBox() const override;
    void forEachActive(const std::function<void(const IndexBox&, float)>& visit) const override;
    float minimum(const IndexBox& box) const override;
    void cellCorners(std::span<const glm::ivec3> cells, std::span<float> corners) const override;
    std::string metadata(const std::string& key) const override;

    const openvdb::FloatGrid& grid() const { return *grid_; }

private:
    openvdb::FloatGrid::ConstPtr grid_;
    openvdb::CoordBBox active_;  // index box of the active voxels and tiles; empty for an empty grid
    float max_ = 0;
    DenseVoxels dense_;  // empty: none
};

// The float grid `name` of the .vdb file `path`; throws Error ("path: what").
openvdb::FloatGrid::Ptr readFloatGrid(const std::string& path, const std::string& name);

}  // namespace brume
