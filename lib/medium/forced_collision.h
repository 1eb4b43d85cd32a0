// Distances along a ray drawn where a piecewise-constant majorant σ̄ puts the first tentative collision,
// conditioned to fall before the ray's end: density σ̄(t) e^{−τ̄(t)} / (1 − e^{−τ̄(end)}), τ̄ the majorant's
// optical depth from the start. Every draw lands in the medium, so thin media are sampled as well as thick.
// And distances drawn uniformly over the same stretches, its guard where the majorant is loose.
#pragma once
#include <cmath>
#include <span>

#include "medium/null_collisions.h"

namespace brume {

class ForcedCollision {
public:
    // `segments` in order along the ray, majorants > 0; kept by reference.
    explicit ForcedCollision(std::span<const MajorantSegment> segments) : segments_(segments) {
        double depth = 0;
        for (const MajorantSegment& s : segments) depth += s.majorant * (s.t1 - s.t0);
        reach_ = -std::expm1(-depth);
    }

    // The chance that a free flight collides before the end (1 over an infinite medium).
    double reach() const { return reach_; }
    // The distance whose majorant optical depth is −ln(1 − u·reach), u in [0, 1).
    double sample(double u) const {
        double target = -std::log1p(-u * reach_), before = 0;
        for (const MajorantSegment& s : segments_) {
            double across = s.majorant * (s.t1 - s.t0);
            if (before + across >= target || &s == &segments_.back())
                return std::min(s.t0 + (target - before) / s.majorant, s.t1);
            before += across;
        }
        return 0;
    }
    double density(double t) const {
        double depth = 0;
        for (const MajorantSegment& s : segments_) {
            if (t < s.t0) return 0;
            if (t <= s.t1) return s.majorant * std::exp(-(depth + s.majorant * (t - s.t0))) / reach_;
            depth += s.majorant * (s.t1 - s.t0);
        }
        return 0;
    }

private:
    std::span<const MajorantSegment> segments_;
    double reach_;
};

// Distances drawn uniformly over the length `segments` cover (their majorants ignored): a density that
// never falls below 1/length, mixed with ForcedCollision where a majorant may exceed the extinction by far
// (smoke's cells), so that the light of smoke deep behind a loose majorant is not left to rare, huge weights.
class UniformCollision {
public:
    explicit UniformCollision(std::span<const MajorantSegment> segments) : segments_(segments) {
        for (const MajorantSegment& s : segments) length_ += s.t1 - s.t0;
    }

    double length() const { return length_; }
    double sample(double u) const {
        double target = u * length_;
        for (const MajorantSegment& s : segments_) {
            if (target <= s.t1 - s.t0 || &s == &segments_.back()) return std::min(s.t0 + target, s.t1);
            target -= s.t1 - s.t0;
        }
        return 0;
    }
    double density(double t) const {
        for (const MajorantSegment& s : segments_)
            if (t >= s.t0 && t <= s.t1) return 1 / length_;
        return 0;
    }

private:
    std::span<const MajorantSegment> segments_;
    double length_ = 0;
};

}  // namespace brume
