// The Henyey–Greenstein phase function (Henyey and Greenstein 1941), Radiance's -mg: the density of the
// direction light takes when a particle scatters it,
//     p(θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}),
// θ between the directions of travel before and after; g > 0 scatters forward, g = 0 is isotropic (1/4π),
// and g is the mean of cos θ.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sampling/warp.h"

namespace brume {

class HenyeyGreenstein {
public:
    // |g| < 1; values closer to ±1 than 0.999 are clamped (the lobe would be a delta the sampling cannot hold).
    explicit HenyeyGreenstein(double g) : g_(std::clamp(g, -0.999, 0.999)) {}

    double g() const { return g_; }
    // Per steradian, of the cosine between the directions of travel.
    double value(double cosTheta) const {
        double d = 1 + g_ * g_ - 2 * g_ * cosTheta;
        return (1 - g_ * g_) / (4 * std::numbers::pi * d * std::sqrt(d));
    }
    // A direction of travel after scattering light that travelled along unit `dir`, distributed by value()
    // (the cumulative distribution inverted exactly).
    dvec3 sample(const dvec3& dir, double u1, double u2) const {
        double cosTheta;
        if (std::abs(g_) < 1e-3) {
            cosTheta = 1 - 2 * u1;
        } else {
            double s = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u1);
            cosTheta = std::clamp((1 + g_ * g_ - s * s) / (2 * g_), -1.0, 1.0);
        }
        double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), phi = 2 * std::numbers::pi * u2;
        return Frame(dir).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
    }

private:
    double g_;
};

}  // namespace brume
