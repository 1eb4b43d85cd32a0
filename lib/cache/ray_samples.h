// What a record's rays saw, one ray per stratum of a grid of rows × columns in each of one or more passes: per
// ray its direction, its radiance, and how far it went before a surface (infinite: none). HemisphereSamples
// and SphereSamples lay the strata out over directions; every sample stands for the same share of them.
#pragma once
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "spectrum/spectrum.h"

namespace brume {

class RaySamples {
public:
    int rows() const { return rows_; }
    int columns() const { return columns_; }
    int strata() const { return rows_ * columns_; }
    int passes() const { return passes_; }
    int count() const { return strata() * passes_; }
    int cell(int row, int column, int pass = 0) const { return (pass * rows_ + row) * columns_ + column; }
    int channels() const { return channels_; }

    // Room for one more ray per stratum; returns the new pass's index.
    int addPass() {
        ++passes_;
        radiance_.resize(size_t(count()) * channels_, 0.f);
        distance_.resize(size_t(count()), std::numeric_limits<double>::infinity());
        direction_.resize(size_t(count()), glm::dvec3(0));
        return passes_ - 1;
    }

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

    double meanBrightness() const {
        double sum = 0;
        for (int i = 0; i < count(); ++i) sum += brightness(i);
        return sum / count();
    }
    // The standard error of the samples' mean brightness, estimated from neighbouring strata: in each row of
    // each pass, columns k, k + 1, k + 2 give d = x_{k+1} − (x_k + x_{k+2})/2, whose square is 3/2 of the
    // variance of one ray where the light's own change from stratum to stratum is linear. (Pairs' differences,
    // x_k − x_{k+1}, count a lamp's glow across the strata as noise: 1.4x the error the triples find in the
    // halo of bench/volume_cache.py, where both agree in a fog's integrating sphere.) Errs high only by the
    // light's curvature over three strata.
    double meanStandardError() const {
        double squares = 0;
        int triples = 0;
        for (int p = 0; p < passes_; ++p)
            for (int j = 0; j < rows_; ++j)
                for (int k = 0; k + 2 < columns_; k += 3, ++triples) {
                    double d = brightness(cell(j, k + 1, p)) -
                               0.5 * (brightness(cell(j, k, p)) + brightness(cell(j, k + 2, p)));
                    squares += d * d / 1.5;
                }
        // Each triple's d²/1.5 estimates one ray's variance; the variance of the samples' sum is count() of them.
        return triples > 0 ? std::sqrt(squares / triples * count()) / count() : 0.0;
    }

protected:
    RaySamples(int rows, int columns, int channels) : rows_(rows), columns_(columns), channels_(channels) {
        radiance_.assign(size_t(count()) * channels_, 0.f);
        distance_.assign(size_t(count()), std::numeric_limits<double>::infinity());
        direction_.assign(size_t(count()), glm::dvec3(0));
    }

private:
    int rows_, columns_, channels_;
    int passes_ = 1;
    std::vector<float> radiance_;
    std::vector<double> distance_;
    std::vector<glm::dvec3> direction_;
};

}  // namespace brume
