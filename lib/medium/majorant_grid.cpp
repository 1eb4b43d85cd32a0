#include "medium/majorant_grid.h"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "medium/density_grid_vdb.h"

namespace brume {

namespace {

// A linear OpenVDB transform as a matrix on column vectors (OpenVDB's matrices act on row vectors).
glm::dmat4 worldFromIndex(const openvdb::math::Transform& transform) {
    const openvdb::Mat4d m = transform.baseMap()->getAffineMap()->getMat4();
    glm::dmat4 g;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g[i][j] = m[i][j];
    return g;
}

// An axis-aligned box mapped by an affine map, as the box around the image.
struct Box {
    dvec3 lo, hi;
    Box mapped(const glm::dmat4& m) const {
        const dvec3 centre(m * glm::dvec4(0.5 * (lo + hi), 1.0));
        const dvec3 half = glm::dmat3(glm::abs(m[0]), glm::abs(m[1]), glm::abs(m[2])) * (0.5 * (hi - lo));
        return {centre - half, centre + half};
    }
};

// Where trilinear interpolation reads the voxels of index box `active`: one voxel beyond their centres.
Box support(const openvdb::CoordBBox& active) {
    const openvdb::Vec3d lo = active.min().asVec3d() - 1.0, hi = active.max().asVec3d() + 1.0;
    return {dvec3(lo.x(), lo.y(), lo.z()), dvec3(hi.x(), hi.y(), hi.z())};
}

}  // namespace

MajorantGrid::MajorantGrid(std::span<const DensityGrid> grids, int voxelsPerCell) {
    if (grids.empty()) return;
    const openvdb::math::Transform& reference = grids[0].voxels().grid->transform();
    const glm::dmat4 referenceFromWorld = glm::inverse(worldFromIndex(reference));
    // Each grid's index space to the first grid's; exactly the identity for frames sharing its transform.
    std::vector<glm::dmat4> referenceFromIndex;
    Box covered{dvec3(std::numeric_limits<double>::infinity()), dvec3(-std::numeric_limits<double>::infinity())};
    for (const DensityGrid& grid : grids) {
        const openvdb::math::Transform& transform = grid.voxels().grid->transform();
        referenceFromIndex.push_back(transform == reference ? glm::dmat4(1.0)
                                                            : referenceFromWorld * worldFromIndex(transform));
        if (grid.voxels().active.empty()) continue;
        const Box b = support(grid.voxels().active).mapped(referenceFromIndex.back());
        covered = {glm::min(covered.lo, b.lo), glm::max(covered.hi, b.hi)};
    }
    if (!(covered.lo.x <= covered.hi.x)) return;  // every grid empty

    const dvec3 origin = glm::floor(covered.lo);
    const auto cellsOf = [&](int size) { return glm::max(glm::ceil((covered.hi - origin) / double(size)), 1.0); };
    voxelsPerCell_ = voxelsPerCell;
    for (dvec3 n = cellsOf(voxelsPerCell_); n.x * n.y * n.z > kMaxCells; n = cellsOf(voxelsPerCell_)) ++voxelsPerCell_;
    n_ = glm::ivec3(cellsOf(voxelsPerCell_));
    const double s = voxelsPerCell_;
    // Cell space from the first grid's index space: (index − origin) / s.
    const glm::dmat4 cellFromReference = glm::dmat4(glm::dvec4(1 / s, 0, 0, 0), glm::dvec4(0, 1 / s, 0, 0),
                                                    glm::dvec4(0, 0, 1 / s, 0), glm::dvec4(-origin / s, 1.0));
    const glm::dmat4 cellFromWorld = cellFromReference * referenceFromWorld;
    cellFromWorld_ = glm::dmat3(cellFromWorld);
    cellOffset_ = dvec3(cellFromWorld[3]);

    // Every non-zero active value (a voxel, or a tile counted once) raises the cells its support meets.
    // Rounding in the mapped boxes can only add a neighbouring cell, never miss one.
    majorants_.assign(std::size_t(n_.x) * n_.y * n_.z, 0.0f);
    for (std::size_t g = 0; g < grids.size(); ++g) {
        const glm::dmat4 cellFromIndex = cellFromReference * referenceFromIndex[g];
        openvdb::CoordBBox box;
        for (auto it = grids[g].voxels().grid->tree().cbeginValueOn(); it; ++it) {
            const float v = *it;
            if (v <= 0 || !it.getBoundingBox(box)) continue;
            const Box cells = support(box).mapped(cellFromIndex);
            const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor(cells.lo)), glm::ivec3(0), n_ - 1);
            const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::ceil(cells.hi)) - 1, glm::ivec3(0), n_ - 1);
            for (int k = lo.z; k <= hi.z; ++k)
                for (int j = lo.y; j <= hi.y; ++j)
                    for (int i = lo.x; i <= hi.x; ++i) {
                        float& m = majorants_[(std::size_t(k) * n_.y + j) * n_.x + i];
                        m = std::max(m, v);
                    }
        }
    }
}

double MajorantGrid::majorant(const dvec3& p) const {
    const dvec3 c = cellFromWorld_ * p + cellOffset_;
    if (majorants_.empty() || !(c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= n_.x && c.y <= n_.y && c.z <= n_.z)) return 0;
    return at(glm::min(glm::ivec3(glm::floor(c)), n_ - 1));
}

}  // namespace brume
