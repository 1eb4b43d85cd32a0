// Where a flame's light comes from, for next-event estimation: a regular grid of cells over the smoke that may
// glow, each weighed by what it emits per unit volume (σ_a B by its brightness, the mean of its octants'
// centres), from which points are drawn — and the density, per steradian seen from a point, of the directions
// such draws give, which is what multiple importance sampling weighs a ray's direction against.
//
// Cells hot only between their sample points weigh 0 and are never drawn: the integrator leaves the light of
// directions no draw can give to the rays that find it (directionDensity 0), so nothing is lost.
#pragma once
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/bounds.h"

namespace brume {

class EmissionCells {
public:
    static constexpr int kMaxCells = 1 << 15;

    EmissionCells() = default;  // none

    // Cells over `box`, cubes `cellSize` wide where that makes at most kMaxCells, else larger; `emitted(p)` ≥ 0
    // says how brightly the smoke at p glows (per unit volume). An empty box or one that emits nowhere gives
    // none (empty()).
    EmissionCells(const Bounds3& box, double cellSize, const std::function<double(const dvec3&)>& emitted);

    bool empty() const { return !(total_ > 0); }
    // ∫ emitted dV, as the cells estimate it.
    double power() const { return total_ * volume_; }
    // The box the cells cover.
    const Bounds3& box() const { return box_; }
    glm::ivec3 resolution() const { return n_; }

    // A point drawn in proportion to the cells' weights, uniform within its cell, for u0..u3 uniform in [0, 1).
    dvec3 sample(double u0, double u1, double u2, double u3) const;
    // The density (per cubic metre) of sample()'s points at p.
    double density(const dvec3& p) const;
    // The density (per steradian) of the directions from `from` to sample()'s points, along unit `dir`:
    // ∫ density(from + t·dir) t² dt over t ≥ 0, in closed form cell by cell.
    double directionDensity(const dvec3& from, const dvec3& dir) const;

private:
    size_t index(const glm::ivec3& c) const { return (size_t(c.z) * n_.y + c.y) * n_.x + c.x; }

    Bounds3 box_;
    dvec3 size_{0};  // of a cell
    glm::ivec3 n_{0};
    double volume_ = 0;              // of a cell
    double total_ = 0;               // Σ weights
    std::vector<double> weights_;    // per cell (z-major), each its mean emission per unit volume
    std::vector<double> cumulative_; // Σ weights up to and including each cell
};

}  // namespace brume
