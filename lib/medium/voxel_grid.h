// A density grid's voxels as Brume sees them, without OpenVDB: its tree lives in a module (lib/medium/openvdb)
// loaded the first time a grid is read, since loading OpenVDB costs about 25 ms, most of a run's start-up,
// and most runs have no smoke.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geometry/bounds.h"

namespace brume {

// Voxels lo..hi of a grid's index space, inclusive.
struct IndexBox {
    glm::ivec3 lo, hi;
};

class VoxelGrid {
public:
    virtual ~VoxelGrid() = default;

    // See DensityGrid.
    virtual Bounds3 bounds() const = 0;
    virtual double density(const dvec3& p) const = 0;
    virtual double maxDensity() const = 0;
    virtual std::uint64_t activeVoxelCount() const = 0;
    virtual std::uint64_t memoryBytes() const = 0;

    // For MajorantGrid: the grid's (linear) map from index space to the world, and whether another grid has
    // exactly the same one.
    virtual glm::dmat4 worldFromIndex() const = 0;
    virtual bool sameTransform(const VoxelGrid& other) const = 0;
    // The index box of the active voxels and tiles; none for an empty grid.
    virtual std::optional<IndexBox> activeBox() const = 0;
    // Every active value above 0 with the index box it covers (a voxel, or a tile once).
    virtual void forEachActive(const std::function<void(const IndexBox&, float)>& visit) const = 0;
    // The smallest value over `box`, 0 where one of its voxels is inactive.
    virtual float minimum(const IndexBox& box) const = 0;
    // For each cell between voxel centres (its lowest corner's index), the 8 voxels at its corners:
    // corners[8n + i + 2j + 4k] the value at cells[n] + (i, j, k), as density() interpolates them.
    virtual void cellCorners(std::span<const glm::ivec3> cells, std::span<float> corners) const = 0;
    // The grid's string metadata `key`, empty where it has none.
    virtual std::string metadata(const std::string& key) const = 0;
};

// The float grid `name` of the .vdb file `path` (see DensityGrid), through the OpenVDB module. Throws Error
// ("path: what"), also when the module cannot be loaded; gives the module's warnings to warn().
std::shared_ptr<const VoxelGrid> readVoxelGrid(const std::string& path, const std::string& name);

}  // namespace brume
