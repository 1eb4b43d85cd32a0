// Upper bounds of a density field on a coarse grid, and the walk of a ray through it: what delta and ratio
// tracking sample against, and how they skip clear air (a segment of majorant 0 costs one callback).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geometry/ray.h"
#include "medium/density_grid.h"

namespace brume {

// Cells are boxes of voxelsPerCell³ voxels of the first grid, aligned with its voxels (so in its index space,
// rotated with it), over the union of the grids' bounds; the cell size grows when needed to keep at most
// kMaxCells cells; voxelsPerCell 0 makes one cell of that union (no empty space skipped inside it). Each cell
// holds the largest density that trilinear interpolation of any of the grids reaches in it — the largest voxel
// whose interpolation support (one voxel each side of its centre) meets the cell — which also bounds any convex
// combination of the grids, such as linear interpolation in time.
// Each cell also holds a lower bound (minorant): the smallest voxel whose support meets the cell, 0 where an
// inactive voxel does, over all the grids (0 unless they share the first grid's transform). Where it equals the
// majorant the smoke is even, and its transmittance closed form.
class MajorantGrid {
public:
    static constexpr int kMaxCells = 1 << 18;
    // Cells larger than this many voxels a side get minorant 0 (finding one reads every voxel around a cell).
    static constexpr int kMaxMinorantCell = 32;

    // Bounds of every convex combination of `grids`, or, given `weights` (one per grid), of that one sum.
    explicit MajorantGrid(std::span<const DensityGrid> grids, int voxelsPerCell = 8,
                          std::span<const double> weights = {});
    explicit MajorantGrid(const DensityGrid& grid, int voxelsPerCell = 8)
        : MajorantGrid(std::span(&grid, 1), voxelsPerCell) {}

    // The majorant at world point p: that of its cell, 0 outside the grid.
    double majorant(const dvec3& p) const;
    double minorant(const dvec3& p) const;

    // Walks ray.at(t) for t in [tmin, tmax] (ray.tmin and ray.tmax are not used) and calls
    // callback(t0, t1, majorant, minorant) -> bool (false stops the walk) for consecutive segments, in order,
    // that cover the part of [tmin, tmax] inside the grid exactly once (each t0 is the previous t1).
    // Consecutive cells of equal bounds make one segment; segments of majorant 0 are reported too. A ray
    // missing the grid gives no segment; outside the grid the density is 0.
    template <typename Callback>
    void forEachBound(const Ray& ray, double tmin, double tmax, Callback&& callback) const;

    glm::ivec3 resolution() const { return n_; }
    int voxelsPerCell() const { return voxelsPerCell_; }

private:
    std::size_t index(const glm::ivec3& c) const { return (std::size_t(c.z) * n_.y + c.y) * n_.x + c.x; }
    // The cell holding world point p, or nothing outside the grid.
    std::optional<std::size_t> cellOf(const dvec3& p) const;
    std::vector<float> cellMaxima(const DensityGrid& grid, const glm::dmat4& cellFromIndex) const;
    std::vector<float> cellMinima(const DensityGrid& grid, const std::vector<float>& most, const dvec3& origin) const;

    // World to cell space, where cell (i, j, k) is the unit cube at (i, j, k) and the grid is [0, n].
    // Affine, so a ray's t is the same in both.
    glm::dmat3 cellFromWorld_{1.0};
    dvec3 cellOffset_{0.0};
    glm::ivec3 n_{0};
    int voxelsPerCell_ = 0;
    std::vector<float> majorants_, minorants_;
};

template <typename Callback>
void MajorantGrid::forEachBound(const Ray& ray, double tmin, double tmax, Callback&& callback) const {
    if (majorants_.empty()) return;
    const dvec3 o = cellFromWorld_ * ray.org + cellOffset_, d = cellFromWorld_ * ray.dir;
    constexpr double kNever = std::numeric_limits<double>::infinity();
    // Clip [tmin, tmax] to the grid's slabs (closed, so rays along a face are walked too).
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (!(o[a] >= 0 && o[a] <= n_[a])) return;
            continue;
        }
        double t0 = -o[a] / d[a], t1 = (n_[a] - o[a]) / d[a];
        tmin = std::max(tmin, std::min(t0, t1));
        tmax = std::min(tmax, std::max(t0, t1));
    }
    if (!(tmin < tmax)) return;
    // Amanatides & Woo (1987), with crossing times recomputed from the faces (no accumulated error).
    const dvec3 p = o + tmin * d;
    glm::ivec3 cell, step;
    dvec3 tNext;
    for (int a = 0; a < 3; ++a) {
        cell[a] = std::clamp(int(std::floor(p[a])), 0, n_[a] - 1);
        step[a] = d[a] > 0 ? 1 : d[a] < 0 ? -1 : 0;
        tNext[a] = step[a] ? (cell[a] + (step[a] > 0) - o[a]) / d[a] : kNever;
    }
    double t0 = tmin;
    std::size_t at = index(cell);
    float majorant = majorants_[at], minorant = minorants_[at];
    for (;;) {
        const double t1 = std::min({tNext.x, tNext.y, tNext.z});
        if (t1 >= tmax) break;
        bool inside = true;
        for (int a = 0; a < 3; ++a)  // every axis crossed at t1: through an edge or corner in one step
            if (tNext[a] == t1) {
                cell[a] += step[a];
                inside = inside && cell[a] >= 0 && cell[a] < n_[a];
                tNext[a] = (cell[a] + (step[a] > 0) - o[a]) / d[a];
            }
        if (!inside) break;  // rounding: left the grid a hair before the clipped tmax
        at = index(cell);
        if (majorants_[at] == majorant && minorants_[at] == minorant) continue;
        if (t1 > t0) {  // a cell crossed in zero length (rounding at an edge) is dropped
            if (!callback(t0, t1, double(majorant), double(minorant))) return;
            t0 = t1;
        }
        majorant = majorants_[at], minorant = minorants_[at];
    }
    callback(t0, tmax, double(majorant), double(minorant));
}

}  // namespace brume
