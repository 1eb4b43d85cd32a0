// A smoke density field read from an OpenVDB grid: sparse (OpenVDB's tree, as in the file), interpolated
// trilinearly between voxel centres, zero outside its active voxels.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include <glm/mat4x4.hpp>

#include "geometry/ray.h"
#include "medium/data_coverage.h"
#include "medium/density_profile.h"
#include "medium/voxel_grid.h"

namespace brume {

// Density is in the file's units (unitless for artists' smoke, kg/m³ of soot for FDS frames); the medium
// scales it to an extinction coefficient. What is made safe at load, once, keeping the tree sparse:
// - NaN, infinite and negative voxels read as 0 (with a warning giving their count);
// - the smoke is the active voxels and tiles: inactive voxels read as 0 whatever the file stored, and a
//   non-zero background (Houdini writes 1.0 for a uniform box) is replaced by 0 with a warning, since a
//   bounded medium cannot honour a value that fills all space;
// - level sets (signed distances, not densities) and non-float grids are refused.
// Copies share the tree; every const member may be called from any thread.
class DensityGrid {
public:
    // The float grid `name` of the .vdb file `path`. Errors are "path: what" and list the file's grids
    // when `name` is not one of them.
    explicit DensityGrid(const std::string& path, const std::string& name = "density")
        : DensityGrid(readVoxelGrid(path, name), path) {}
    // `source` names the grid in messages ("source: brume:data: …" where its coverage is malformed).
    explicit DensityGrid(std::shared_ptr<const VoxelGrid> voxels, const std::string& source = "grid");

    // Where the density can be non-zero: trilinear interpolation reaches one voxel beyond the centres of
    // the outermost active voxels (tiles included). Empty for an empty grid.
    const Bounds3& bounds() const { return bounds_; }
    // The density at world point p (0 outside bounds()).
    double density(const dvec3& p) const { return voxels_->density(p); }
    // ∫ density(ray.org + t ray.dir) dt over [t0, t1], exact up to rounding: the ray is walked through the
    // cells between voxel centres in index space, within each of which the density along a line is a cubic
    // in t (trilinear interpolation), which two-point Gauss–Legendre integrates exactly. Per cell the ray
    // crosses (about three per voxel length), its eight corner voxels, four of them shared with the cell before.
    double integral(const Ray& ray, double t0, double t1) const;
    // The density along the ray over [t0, t1], cell by cell (DensityProfile): the same walk as integral().
    DensityProfile profile(const Ray& ray, double t0, double t1) const;

    double maxDensity() const { return voxels_->maxDensity(); }
    // Voxels holding smoke, active tiles counted voxel by voxel.
    std::uint64_t activeVoxelCount() const { return voxels_->activeVoxelCount(); }
    // Bytes held by the tree (OpenVDB's count).
    std::uint64_t memoryBytes() const { return voxels_->memoryBytes(); }

    const VoxelGrid& voxels() const { return *voxels_; }
    // Where a simulation's domain has data, from the grid's metadata (DataCoverage); no domain without it.
    const DataCoverage& coverage() const { return coverage_; }

private:
    template <class F>
    void forEachCell(const Ray& ray, double t0, double t1, F&& f) const;

    std::shared_ptr<const VoxelGrid> voxels_;
    Bounds3 bounds_;  // the voxels' (computed once: it maps the index box's corners to the world)
    glm::dmat4 indexFromWorld_;
    DataCoverage coverage_;
};

}  // namespace brume
