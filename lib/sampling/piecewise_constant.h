// A density over [0, 1) that is constant over equal bins, weighed by given values, mixed with a uniform share
// that keeps every draw's weight bounded: f/p ≤ f/share wherever the bins' values guessed f wrong. Drawn by
// inverting its cumulative distribution, so stratified numbers give stratified draws (pbrt's
// PiecewiseConstant1D, with the defensive mixture of Hesterberg 1995).
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace brume {

class PiecewiseConstant {
public:
    // `weights` ≥ 0 per bin (all 0, or none: uniform); `uniform` in (0, 1], the uniform share.
    PiecewiseConstant(std::span<const double> weights, double uniform) {
        double total = 0;
        for (double w : weights) total += std::max(0.0, w);
        const size_t n = std::max<size_t>(1, weights.size());
        const double guided = total > 0 ? 1 - uniform : 0;
        cumulative_.push_back(0);
        for (size_t i = 0; i < n; ++i) {
            double w = i < weights.size() && total > 0 ? std::max(0.0, weights[i]) / total : 0;
            density_.push_back((1 - guided) + guided * w * double(n));
            cumulative_.push_back(cumulative_.back() + density_.back() / double(n));
        }
        cumulative_.back() = 1;
    }

    // The x in [0, 1) where the cumulative distribution reaches u in [0, 1).
    double sample(double u) const {
        const size_t n = density_.size();
        size_t i = size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin()) - 1;
        i = std::min(i, n - 1);
        while (density_[i] <= 0 && i + 1 < n) ++i;  // (u on the edge of a bin of no mass)
        double x = (double(i) + (u - cumulative_[i]) * double(n) / density_[i]) / double(n);
        return std::clamp(x, double(i) / double(n), std::nextafter(double(i + 1) / double(n), 0.0));
    }
    double density(double x) const {
        if (!(x >= 0 && x < 1)) return 0;
        return density_[std::min(density_.size() - 1, size_t(x * double(density_.size())))];
    }

private:
    std::vector<double> density_;     // per bin
    std::vector<double> cumulative_;  // at each bin's start, and 1 at the end
};

}  // namespace brume
