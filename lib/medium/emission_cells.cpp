#include "medium/emission_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brume {

EmissionCells::EmissionCells(const Bounds3& box, double cellSize,
                             const std::function<double(const dvec3&)>& emitted) {
    if (box.empty() || !(cellSize > 0)) return;
    const dvec3 extent = box.hi - box.lo;
    if (!(extent.x > 0 && extent.y > 0 && extent.z > 0)) return;
    // Grow the cells until there are few enough of them.
    for (double edge = cellSize;; edge *= 1.25) {
        glm::dvec3 n = glm::ceil(extent / edge);
        if (n.x * n.y * n.z <= kMaxCells) {
            n_ = glm::ivec3(n);
            break;
        }
    }
    box_ = box;
    size_ = extent / dvec3(n_);
    volume_ = size_.x * size_.y * size_.z;
    weights_.assign(size_t(n_.x) * n_.y * n_.z, 0.0);
    cumulative_.resize(weights_.size());
    glm::ivec3 c;
    for (c.z = 0; c.z < n_.z; ++c.z)
        for (c.y = 0; c.y < n_.y; ++c.y)
            for (c.x = 0; c.x < n_.x; ++c.x) {
                double sum = 0;
                for (int octant = 0; octant < 8; ++octant) {
                    dvec3 at(0.25 + 0.5 * (octant & 1), 0.25 + 0.5 * ((octant >> 1) & 1), 0.25 + 0.5 * (octant >> 2));
                    double e = emitted(box.lo + (dvec3(c) + at) * size_);
                    if (e > 0 && std::isfinite(e)) sum += e;
                }
                weights_[index(c)] = sum / 8;
            }
    for (size_t i = 0; i < weights_.size(); ++i) cumulative_[i] = total_ += weights_[i];
}

dvec3 EmissionCells::sample(double u0, double u1, double u2, double u3) const {
    // The first cell whose cumulative weight exceeds u0·total: never one of weight 0.
    auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u0 * total_);
    size_t i = std::min(size_t(it - cumulative_.begin()), cumulative_.size() - 1);
    while (weights_[i] <= 0 && i > 0) --i;  // (u0·total rounded onto the last cumulative value)
    glm::ivec3 c(int(i % n_.x), int(i / n_.x % n_.y), int(i / (size_t(n_.x) * n_.y)));
    return box_.lo + (dvec3(c) + dvec3(u1, u2, u3)) * size_;
}

double EmissionCells::density(const dvec3& p) const {
    if (empty()) return 0;
    dvec3 q = (p - box_.lo) / size_;
    if (!(q.x >= 0 && q.y >= 0 && q.z >= 0 && q.x < n_.x && q.y < n_.y && q.z < n_.z)) return 0;
    return weights_[index(glm::ivec3(q))] / (total_ * volume_);
}

// Amanatides & Woo's walk through the cells the half-line crosses, each adding its density times
// ∫ t² dt = (t1³ − t0³)/3 over the stretch it holds.
double EmissionCells::directionDensity(const dvec3& from, const dvec3& dir) const {
    if (empty()) return 0;
    double tmin = 0, tmax = std::numeric_limits<double>::infinity();
    if (!clipToBox(box_, from, dir, tmin, tmax) || !(tmin < tmax)) return 0;
    const dvec3 o = (from - box_.lo) / size_, d = dir / size_;  // in cells; t is unchanged
    glm::ivec3 cell, step;
    dvec3 tNext;
    const dvec3 p = o + tmin * d;
    for (int a = 0; a < 3; ++a) {
        cell[a] = std::clamp(int(std::floor(p[a])), 0, n_[a] - 1);
        step[a] = d[a] > 0 ? 1 : d[a] < 0 ? -1 : 0;
        tNext[a] = step[a] ? (cell[a] + (step[a] > 0) - o[a]) / d[a] : std::numeric_limits<double>::infinity();
    }
    double sum = 0, t0 = tmin;
    for (;;) {
        double t1 = std::min({tNext.x, tNext.y, tNext.z, tmax});
        double w = weights_[index(cell)];
        if (w > 0 && t1 > t0) sum += w * (t1 - t0) * (t1 * t1 + t1 * t0 + t0 * t0) / 3;
        if (t1 >= tmax) break;
        bool inside = true;
        for (int a = 0; a < 3; ++a)
            if (tNext[a] == t1) {
                cell[a] += step[a];
                inside = inside && cell[a] >= 0 && cell[a] < n_[a];
                tNext[a] = (cell[a] + (step[a] > 0) - o[a]) / d[a];
            }
        if (!inside) break;
        t0 = t1;
    }
    return sum / (total_ * volume_);
}

}  // namespace brume
