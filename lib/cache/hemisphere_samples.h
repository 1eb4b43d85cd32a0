// The light a record is made from: radiance and distance seen along stratified, cosine-distributed
// directions over a point's hemisphere (Ward & Heckbert 1992's M rows in θ by N columns in φ), and samples
// aimed at known light besides them.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "cache/ray_samples.h"
#include "sampling/warp.h"

namespace brume {

// A sample aimed at known light rather than drawn over the hemisphere (the sky through a window, a sun
// patch): its direction, the irradiance it adds to the record's, and how far along it that light comes
// from (the window, where the sky's light is cut off; the patch).
struct AimedSample {
    dvec3 dir;
    Spectrum irradiance;
    double distance;
};

class HemisphereSamples : public RaySamples {
public:
    // About `divisions` cells, N ≈ πM as Ward and Heckbert advise, at least 2 × 4.
    HemisphereSamples(const dvec3& point, const dvec3& normal, int divisions, int channels)
        : RaySamples(rowsFor(divisions), columnsFor(divisions), channels), point_(point), frame_(normal) {}

    const dvec3& point() const { return point_; }
    const Frame& frame() const { return frame_; }

    // sin²θ at the lower edge of a row (cosine-weighted strata are equal steps of sin²θ), φ at a column's edge.
    double sin2Edge(int row) const { return double(row) / rows(); }
    double phiEdge(int column) const { return 2 * std::numbers::pi * column / columns(); }

    using RaySamples::direction;  // a sample's, by its index
    // The direction through (u, v) ∈ [0,1)² of a cell, in world space.
    dvec3 direction(int row, int column, double u, double v) const {
        double sin2 = (row + u) / rows(), phi = 2 * std::numbers::pi * (column + v) / columns();
        double s = std::sqrt(sin2);
        return frame_.toWorld(dvec3(s * std::cos(phi), s * std::sin(phi), std::sqrt(std::max(0.0, 1 - sin2))));
    }

    std::vector<AimedSample>& aimed() { return aimed_; }
    const std::vector<AimedSample>& aimed() const { return aimed_; }

private:
    static int rowsFor(int divisions) { return std::max(2, int(std::lround(std::sqrt(divisions / std::numbers::pi)))); }
    static int columnsFor(int divisions) { return std::max(4, int(std::lround(double(divisions) / rowsFor(divisions)))); }

    dvec3 point_;
    Frame frame_;
    std::vector<AimedSample> aimed_;
};

}  // namespace brume
