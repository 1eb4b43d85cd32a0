// The light a volume record is made from: radiance and distance seen along stratified directions over the
// whole sphere about a point in a medium (M rows of equal steps of cos θ by N ≈ 2M columns of φ: equal solid
// angles, so each sample stands for 4π/(MN) steradians).
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "cache/ray_samples.h"

namespace brume {

using glm::dvec3;

class SphereSamples : public RaySamples {
public:
    // About `divisions` cells, at least 2 × 4.
    SphereSamples(const dvec3& point, int divisions, int channels)
        : RaySamples(rowsFor(divisions), columnsFor(divisions), channels), point_(point) {}

    const dvec3& point() const { return point_; }
    // The solid angle each sample stands for.
    double solidAngle() const { return 4 * std::numbers::pi / count(); }

    using RaySamples::direction;  // a sample's, by its index
    // The direction through (u, v) ∈ [0,1)² of a cell.
    dvec3 direction(int row, int column, double u, double v) const {
        double z = 1 - 2 * (row + u) / rows(), phi = 2 * std::numbers::pi * (column + v) / columns();
        double s = std::sqrt(std::max(0.0, 1 - z * z));
        return dvec3(s * std::cos(phi), s * std::sin(phi), z);
    }

private:
    static int rowsFor(int divisions) { return std::max(2, int(std::lround(std::sqrt(divisions / 2.0)))); }
    static int columnsFor(int divisions) { return std::max(4, int(std::lround(double(divisions) / rowsFor(divisions)))); }

    dvec3 point_;
};

}  // namespace brume
