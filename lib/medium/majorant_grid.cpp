#include "medium/majorant_grid.h"

#include <glm/mat4x4.hpp>
#include <algorithm>
#include <glm/matrix.hpp>

namespace brume {

namespace {

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
Box support(const IndexBox& active) { return {dvec3(active.lo) - 1.0, dvec3(active.hi) + 1.0}; }

}  // namespace

MajorantGrid::MajorantGrid(std::span<const DensityGrid> grids, int voxelsPerCell, std::span<const double> weights) {
    if (grids.empty()) return;
    const VoxelGrid& reference = grids[0].voxels();
    const glm::dmat4 referenceFromWorld = glm::inverse(reference.worldFromIndex());
    // Each grid's index space to the first grid's; exactly the identity for frames sharing its transform.
    std::vector<glm::dmat4> referenceFromIndex;
    Box covered{dvec3(std::numeric_limits<double>::infinity()), dvec3(-std::numeric_limits<double>::infinity())};
    for (const DensityGrid& grid : grids) {
        const VoxelGrid& voxels = grid.voxels();
        referenceFromIndex.push_back(voxels.sameTransform(reference) ? glm::dmat4(1.0)
                                                                     : referenceFromWorld * voxels.worldFromIndex());
        const std::optional<IndexBox> active = voxels.activeBox();
        if (!active) continue;
        const Box b = support(*active).mapped(referenceFromIndex.back());
        covered = {glm::min(covered.lo, b.lo), glm::max(covered.hi, b.hi)};
    }
    if (!(covered.lo.x <= covered.hi.x)) return;  // every grid empty

    const dvec3 origin = glm::floor(covered.lo);
    const auto cellsOf = [&](int size) { return glm::max(glm::ceil((covered.hi - origin) / double(size)), 1.0); };
    // The cell's edges in voxels: voxelsPerCell³, or with 0 the whole covered box as one cell.
    dvec3 s = glm::max(glm::ceil(covered.hi - origin), 1.0);
    voxelsPerCell_ = voxelsPerCell;
    if (voxelsPerCell_ > 0) {
        for (dvec3 n = cellsOf(voxelsPerCell_); n.x * n.y * n.z > kMaxCells; n = cellsOf(voxelsPerCell_)) ++voxelsPerCell_;
        n_ = glm::ivec3(cellsOf(voxelsPerCell_));
        s = dvec3(voxelsPerCell_);
    } else {
        n_ = glm::ivec3(1);
    }
    // Cell space from the first grid's index space: (index − origin) / s.
    const glm::dmat4 cellFromReference = glm::dmat4(glm::dvec4(1 / s.x, 0, 0, 0), glm::dvec4(0, 1 / s.y, 0, 0),
                                                    glm::dvec4(0, 0, 1 / s.z, 0), glm::dvec4(-origin / s, 1.0));
    const glm::dmat4 cellFromWorld = cellFromReference * referenceFromWorld;
    cellFromWorld_ = glm::dmat3(cellFromWorld);
    cellOffset_ = dvec3(cellFromWorld[3]);

    // Bounds of any convex combination of the grids (an interval of time): the largest maximum and the
    // smallest minimum; of the one weighted sum `weights` gives (an instant): the weighted sums.
    const bool shared = std::all_of(referenceFromIndex.begin(), referenceFromIndex.end(),
                                    [](const glm::dmat4& m) { return m == glm::dmat4(1.0); });
    const bool withMinorants = shared && voxelsPerCell_ > 0 && voxelsPerCell_ <= kMaxMinorantCell;
    const std::size_t cells = std::size_t(n_.x) * n_.y * n_.z;
    majorants_.assign(cells, 0.0f);
    minorants_.assign(cells, weights.empty() ? std::numeric_limits<float>::infinity() : 0.0f);
    for (std::size_t g = 0; g < grids.size(); ++g) {
        std::vector<float> most = cellMaxima(grids[g], cellFromReference * referenceFromIndex[g]);
        std::vector<float> least = withMinorants ? cellMinima(grids[g], most, origin) : std::vector<float>(cells, 0.0f);
        for (std::size_t c = 0; c < cells; ++c) {
            if (weights.empty()) {
                majorants_[c] = std::max(majorants_[c], most[c]);
                minorants_[c] = std::min(minorants_[c], least[c]);
            } else {
                majorants_[c] += float(weights[g]) * most[c];
                minorants_[c] += float(weights[g]) * least[c];
            }
        }
    }
    // Weighted sums round, and so does interpolation in time: widen both bounds by far more than that.
    for (std::size_t c = 0; c < cells; ++c) {
        if (!weights.empty()) majorants_[c] *= 1 + 0x1p-20f;
        minorants_[c] = std::min(minorants_[c] * (1 - 0x1p-20f), majorants_[c]);
    }
}

// Every non-zero active value of `grid` (a voxel, or a tile counted once) raises the cells its support meets.
// Rounding in the mapped boxes can only add a neighbouring cell, never miss one.
std::vector<float> MajorantGrid::cellMaxima(const DensityGrid& grid, const glm::dmat4& cellFromIndex) const {
    std::vector<float> most(std::size_t(n_.x) * n_.y * n_.z, 0.0f);
    grid.voxels().forEachActive([&](const IndexBox& box, float v) {
        const Box cells = support(box).mapped(cellFromIndex);
        const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor(cells.lo)), glm::ivec3(0), n_ - 1);
        const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::ceil(cells.hi)) - 1, glm::ivec3(0), n_ - 1);
        for (int k = lo.z; k <= hi.z; ++k)
            for (int j = lo.y; j <= hi.y; ++j)
                for (int i = lo.x; i <= hi.x; ++i) {
                    float& m = most[index({i, j, k})];
                    m = std::max(m, v);
                }
    });
    return most;
}

// The smallest value over the voxels whose support meets each cell where `most` has smoke (0 where an
// inactive voxel does); the grid shares the reference grid's transform.
std::vector<float> MajorantGrid::cellMinima(const DensityGrid& grid, const std::vector<float>& most,
                                            const dvec3& origin) const {
    std::vector<float> least(most.size(), 0.0f);
    const int s = voxelsPerCell_;
    for (int k = 0; k < n_.z; ++k)
        for (int j = 0; j < n_.y; ++j)
            for (int i = 0; i < n_.x; ++i) {
                if (!(most[index({i, j, k})] > 0)) continue;
                const glm::ivec3 lo(int(origin.x) + s * i - 1, int(origin.y) + s * j - 1, int(origin.z) + s * k - 1);
                least[index({i, j, k})] = grid.voxels().minimum({lo, lo + s + 2});
            }
    return least;
}

std::optional<std::size_t> MajorantGrid::cellOf(const dvec3& p) const {
    const dvec3 c = cellFromWorld_ * p + cellOffset_;
    if (majorants_.empty() || !(c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= n_.x && c.y <= n_.y && c.z <= n_.z))
        return std::nullopt;
    return index(glm::min(glm::ivec3(glm::floor(c)), n_ - 1));
}

double MajorantGrid::majorant(const dvec3& p) const {
    auto cell = cellOf(p);
    return cell ? majorants_[*cell] : 0.0;
}

double MajorantGrid::minorant(const dvec3& p) const {
    auto cell = cellOf(p);
    return cell ? minorants_[*cell] : 0.0;
}

}  // namespace brume
