#include "medium/density_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "util/error.h"

namespace brume {

namespace {
DataCoverage coverageOf(const VoxelGrid& voxels, const std::string& source) {
    try {
        return DataCoverage::parse(voxels.metadata("brume:domain"), voxels.metadata("brume:data"),
                                   voxels.metadata("brume:data_note"));
    } catch (const Error& e) {
        throw Error(source + ": " + e.what());
    }
}
}  // namespace

DensityGrid::DensityGrid(std::shared_ptr<const VoxelGrid> voxels, const std::string& source)
    : voxels_(std::move(voxels)),
      bounds_(voxels_->bounds()),
      indexFromWorld_(glm::inverse(voxels_->worldFromIndex())),
      coverage_(coverageOf(*voxels_, source)) {}

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

// The trilinear interpolation of a cell's corners c along p(s) = p + s·d (the cell's own coordinates) as a
// cubic in s: lerps along x of constants are linear in s, along y of those quadratic, along z cubic.
std::array<double, 4> cellCubic(const float* c, const dvec3& p, const dvec3& d) {
    using Poly = std::array<double, 4>;
    // q + (w0 + w1·s)·(r − q), for q and r of degree below 3 (the product stays a cubic).
    auto lerp = [](const Poly& q, const Poly& r, double w0, double w1) {
        Poly out;
        for (int k = 0; k < 4; ++k) out[k] = q[k] + w0 * (r[k] - q[k]) + (k > 0 ? w1 * (r[k - 1] - q[k - 1]) : 0);
        return out;
    };
    auto constant = [&](int i) { return Poly{double(c[i]), 0, 0, 0}; };
    auto alongX = [&](int i) { return lerp(constant(i), constant(i + 1), p.x, d.x); };
    Poly y0 = lerp(alongX(0), alongX(2), p.y, d.y), y1 = lerp(alongX(4), alongX(6), p.y, d.y);
    return lerp(y0, y1, p.z, d.z);
}

struct Piece {
    double a, b;
};

}  // namespace

// Amanatides & Woo's walk through the cells between voxel centres that [t0, t1] crosses, in index space (where
// voxel centres are the integers and the cells [i, i+1]³), calling f(corners, o, d, a, b) per stretch [a, b] in
// a cell: its 8 corner voxels (as VoxelGrid::cellCorners gives them) and the ray as o + t·d in the cell's own
// coordinates. Corners are read in batches of kBatch cells.
template <class F>
void DensityGrid::forEachCell(const Ray& ray, double t0, double t1, F&& f) const {
    if (!clipToBox(bounds(), ray.org, ray.dir, t0, t1) || !(t1 > t0)) return;  // no density outside
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
    constexpr std::size_t kBatch = 64;
    std::array<glm::ivec3, kBatch> cells;
    std::array<Piece, kBatch> pieces;
    std::array<float, 8 * kBatch> corners;
    std::size_t count = 0;
    auto flush = [&] {
        voxels_->cellCorners(std::span(cells.data(), count), corners);
        for (std::size_t n = 0; n < count; ++n) f(&corners[8 * n], o - dvec3(cells[n]), d, pieces[n].a, pieces[n].b);
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
}

double DensityGrid::integral(const Ray& ray, double t0, double t1) const {
    double sum = 0;
    forEachCell(ray, t0, t1, [&](const float* c, const dvec3& o, const dvec3& d, double a, double b) {
        sum += cellIntegral(c, o, d, a, b);
    });
    return sum;
}

DensityProfile DensityGrid::profile(const Ray& ray, double t0, double t1) const {
    DensityProfile out;
    forEachCell(ray, t0, t1, [&](const float* c, const dvec3& o, const dvec3& d, double a, double b) {
        out.append(a, b, cellCubic(c, o + a * d, d));
    });
    return out;
}

}  // namespace brume
