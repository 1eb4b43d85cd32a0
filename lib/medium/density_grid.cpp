#include "medium/density_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace brume {

DensityGrid::DensityGrid(std::shared_ptr<const VoxelGrid> voxels)
    : voxels_(std::move(voxels)),
      bounds_(voxels_->bounds()),
      indexFromWorld_(glm::inverse(voxels_->worldFromIndex())) {}

namespace {

// ∫ over [a, b] of the trilinear interpolation of a cell's corners c (c[i + 2j + 4k] at (i, j, k)) along
// p(t) = o + t d, in the cell's own coordinates: a cubic in t, which two-point Gauss–Legendre integrates
// exactly.
double cellIntegral(const float* c, const dvec3& o, const dvec3& d, double a, double b) {
    const double node = 0.5 / std::sqrt(3.0), mid = 0.5 * (a + b), half = node * (b - a);
    auto at = [&](double t) {
        const dvec3 p = o + t * d;
        auto lerp = [](double x, double y, double w) { return x + w * (y - x); };
        double x00 = lerp(c[0], c[1], p.x), x10 = lerp(c[2], c[3], p.x), x01 = lerp(c[4], c[5], p.x),
               x11 = lerp(c[6], c[7], p.x);
        return lerp(lerp(x00, x10, p.y), lerp(x01, x11, p.y), p.z);
    };
    return 0.5 * (b - a) * (at(mid - half) + at(mid + half));
}

struct Piece {
    double a, b;
};

}  // namespace

double DensityGrid::integral(const Ray& ray, double t0, double t1) const {
    if (!clipToBox(bounds(), ray.org, ray.dir, t0, t1) || !(t1 > t0)) return 0;  // no density outside
    // In index space voxel centres are the integers; the cells between them are [i, i+1]³.
    const dvec3 o = dvec3(indexFromWorld_ * glm::dvec4(ray.org, 1)), d = dvec3(indexFromWorld_ * glm::dvec4(ray.dir, 0));
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const dvec3 start = o + t0 * d;
    glm::ivec3 cell = glm::ivec3(glm::floor(start));
    dvec3 next, step;
    glm::ivec3 move;
    for (int a = 0; a < 3; ++a) {
        move[a] = d[a] > 0 ? 1 : -1;
        if (d[a] == 0) {
            next[a] = step[a] = kNever;
            continue;
        }
        // Going down from exactly a cell's lowest face, the first cell is the one below.
        if (d[a] < 0 && start[a] == double(cell[a])) --cell[a];
        next[a] = t0 + (double(cell[a] + (d[a] > 0)) - start[a]) / d[a];
        step[a] = 1 / std::abs(d[a]);
    }
    // Pieces in batches of kBatch: each batch's corners in one call.
    constexpr std::size_t kBatch = 64;
    std::array<glm::ivec3, kBatch> cells;
    std::array<Piece, kBatch> pieces;
    std::array<float, 8 * kBatch> corners;
    std::size_t count = 0;
    double sum = 0;
    auto flush = [&] {
        voxels_->cellCorners(std::span(cells.data(), count), corners);
        for (std::size_t n = 0; n < count; ++n)
            sum += cellIntegral(&corners[8 * n], o - dvec3(cells[n]), d, pieces[n].a, pieces[n].b);
        count = 0;
    };
    for (double a = t0; a < t1;) {
        int axis = next.x <= next.y ? (next.x <= next.z ? 0 : 2) : (next.y <= next.z ? 1 : 2);
        double b = std::min(next[axis], t1);
        if (b > a) {
            cells[count] = cell, pieces[count] = {a, b};
            if (++count == kBatch) flush();
        }
        a = b;
        next[axis] += step[axis];
        cell[axis] += move[axis];
    }
    flush();
    return sum;
}

}  // namespace brume
