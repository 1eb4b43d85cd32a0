// What a record's rays saw, one ray per stratum of a grid of rows × columns: per ray its direction, its
// radiance, and how far it went before a surface (infinite: none). HemisphereSamples and SphereSamples lay
// the strata out over directions.
#pragma once
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "spectrum/spectrum.h"

namespace brume {

class RaySamples {
public:
    int rows() const { return rows_; }
    int columns() const { return columns_; }
    int count() const { return rows_ * columns_; }
    int cell(int row, int column) const { return row * columns_ + column; }
    int channels() const { return channels_; }

    void set(int index, const glm::dvec3& dir, const Spectrum& radiance, double distance) {
        direction_[index] = dir;
        for (int c = 0; c < channels_; ++c) radiance_[size_t(index) * channels_ + c] = radiance[c];
        distance_[index] = distance > 0 ? distance : std::numeric_limits<double>::infinity();
    }
    float radiance(int index, int channel) const { return radiance_[size_t(index) * channels_ + channel]; }
    // The sample's radiance with Radiance's luminance weights (brightness() in spectrum.h).
    float brightness(int index) const { return brightnessOf(&radiance_[size_t(index) * channels_], channels_); }
    double distance(int index) const { return distance_[index]; }
    // The harmonic mean of the rays' distances (infinite where none met a surface).
    double harmonicMeanDistance() const {
        double inverse = 0;
        for (double d : distance_) inverse += 1 / d;
        return inverse > 0 ? count() / inverse : std::numeric_limits<double>::infinity();
    }
    const glm::dvec3& direction(int index) const { return direction_[index]; }

protected:
    RaySamples(int rows, int columns, int channels) : rows_(rows), columns_(columns), channels_(channels) {
        radiance_.assign(size_t(count()) * channels_, 0.f);
        distance_.assign(size_t(count()), std::numeric_limits<double>::infinity());
        direction_.assign(size_t(count()), glm::dvec3(0));
    }

private:
    int rows_, columns_, channels_;
    std::vector<float> radiance_;
    std::vector<double> distance_;
    std::vector<glm::dvec3> direction_;
};

}  // namespace brume
