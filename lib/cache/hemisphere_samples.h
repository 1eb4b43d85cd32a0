// The light a record is made from: radiance and distance seen along stratified, cosine-distributed
// directions over a point's hemisphere (Ward & Heckbert 1992's M rows in θ by N columns in φ), and samples
// aimed at known light besides them.
#pragma once
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "sampling/warp.h"
#include "spectrum/spectrum.h"

namespace brume {

// A sample aimed at known light rather than drawn over the hemisphere (the sky through a window, a sun
// patch): its direction, the irradiance it adds to the record's, and how far along it that light comes
// from (the window, where the sky's light is cut off; the patch).
struct AimedSample {
    dvec3 dir;
    Spectrum irradiance;
    double distance;
};

class HemisphereSamples {
public:
    // About `divisions` cells, N ≈ πM as Ward and Heckbert advise, at least 2 × 4.
    HemisphereSamples(const dvec3& point, const dvec3& normal, int divisions, int channels)
        : point_(point), frame_(normal), channels_(channels) {
        rows_ = std::max(2, int(std::lround(std::sqrt(divisions / std::numbers::pi))));
        columns_ = std::max(4, int(std::lround(double(divisions) / rows_)));
        radiance_.assign(size_t(count()) * channels_, 0.f);
        distance_.assign(size_t(count()), std::numeric_limits<double>::infinity());
        direction_.assign(size_t(count()), dvec3(0));
    }

    int rows() const { return rows_; }
    int columns() const { return columns_; }
    int count() const { return rows_ * columns_; }
    int channels() const { return channels_; }
    const dvec3& point() const { return point_; }
    const Frame& frame() const { return frame_; }
    int cell(int row, int column) const { return row * columns_ + column; }

    // sin²θ at the lower edge of a row (cosine-weighted strata are equal steps of sin²θ), φ at a column's edge.
    double sin2Edge(int row) const { return double(row) / rows_; }
    double phiEdge(int column) const { return 2 * std::numbers::pi * column / columns_; }

    // The direction through (u, v) ∈ [0,1)² of a cell, in world space.
    dvec3 direction(int row, int column, double u, double v) const {
        double sin2 = (row + u) / rows_, phi = 2 * std::numbers::pi * (column + v) / columns_;
        double s = std::sqrt(sin2);
        return frame_.toWorld(dvec3(s * std::cos(phi), s * std::sin(phi), std::sqrt(std::max(0.0, 1 - sin2))));
    }

    void set(int index, const dvec3& dir, const Spectrum& radiance, double distance) {
        direction_[index] = dir;
        for (int c = 0; c < channels_; ++c) radiance_[size_t(index) * channels_ + c] = radiance[c];
        distance_[index] = distance > 0 ? distance : std::numeric_limits<double>::infinity();
    }
    float radiance(int index, int channel) const { return radiance_[size_t(index) * channels_ + channel]; }
    // The sample's radiance with Radiance's luminance weights (brightness() in spectrum.h).
    float brightness(int index) const { return brightnessOf(&radiance_[size_t(index) * channels_], channels_); }
    double distance(int index) const { return distance_[index]; }
    const dvec3& direction(int index) const { return direction_[index]; }

    std::vector<AimedSample>& aimed() { return aimed_; }
    const std::vector<AimedSample>& aimed() const { return aimed_; }

private:
    dvec3 point_;
    Frame frame_;
    int channels_;
    int rows_ = 0, columns_ = 0;
    std::vector<float> radiance_;
    std::vector<double> distance_;
    std::vector<dvec3> direction_;
    std::vector<AimedSample> aimed_;
};

}  // namespace brume
