// Distributions of distances along a ray, each given by its cumulative distribution and density, and the
// mixture of them that draws distances (DistanceMixture): where a piecewise-constant majorant σ̄ puts the first
// tentative collision, conditioned to fall before the ray's end: density σ̄(t) e^{−τ̄(t)} / (1 − e^{−τ̄(end)}),
// τ̄ the majorant's optical depth from the start (every draw lands in the medium, so thin media are sampled as
// well as thick); uniform over the same stretches, its guard where the majorant is loose; and in proportion to
// 1/r² from a small source beside the ray, to find the light it scatters from the media near it; and where
// the true extinction σ(t) puts the first collision, σ(t) e^{−τ(t)} (DepthCollision), from the smoke's exact
// density along the ray.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/ray.h"
#include "medium/density_profile.h"
#include "medium/henyey_greenstein.h"
#include "medium/null_collisions.h"

namespace brume {

struct CdfAndDensity {
    double cdf, density;
};

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
    // The chance of a draw before t, and the density at t.
    CdfAndDensity cdfAndDensity(double t) const {
        double depth = 0;
        for (const MajorantSegment& s : segments_) {
            if (t < s.t0) return {-std::expm1(-depth) / reach_, 0};
            if (t <= s.t1) {
                double d = depth + s.majorant * (t - s.t0);
                return {-std::expm1(-d) / reach_, s.majorant * std::exp(-d) / reach_};
            }
            depth += s.majorant * (s.t1 - s.t0);
        }
        return {1, 0};
    }

private:
    std::span<const MajorantSegment> segments_;
    double reach_;
};

// Distances in proportion to σ(t) e^{−τ(t)} / (1 − e^{−τ(end)}), σ = Σ scale_i × density_i(t) of density
// profiles along the ray and τ its integral from their start: where the first real collision falls (analog
// tracking's free flight, conditioned to fall before the end) with τ exact, not a majorant's. What the smoke
// emits, σ_a B e^{−τ}, then weighs B times (1 − e^{−τ(end)}) a draw, whatever the density's profile; a
// majorant's exponential over a loose cell instead puts its draws before the smoke starts, where the smoke of a
// thick flame's ramping edge gives no light, and the light it does give to rare draws of huge weight.
class DepthCollision {
public:
    struct Term {
        const DensityProfile* profile;  // kept by reference
        double scale;
    };
    explicit DepthCollision(std::vector<Term> terms) : terms_(std::move(terms)) {
        double depth = 0;
        for (const Term& term : terms_) depth += term.scale * term.profile->total();
        reach_ = -std::expm1(-depth);
    }

    // The chance that a free flight collides before the end.
    double reach() const { return reach_; }
    CdfAndDensity cdfAndDensity(double t) const {
        double depth = 0, sigma = 0;
        for (const Term& term : terms_) {
            DensityProfile::Point p = term.profile->at(t);
            depth += term.scale * p.integral, sigma += term.scale * p.density;
        }
        return {-std::expm1(-depth) / reach_, sigma * std::exp(-depth) / reach_};
    }
    // Of one term, the distance where the cumulative distribution reaches u, in closed form but for the
    // inverse of the profile's integral (DensityProfile::inverse): no search over the whole ray.
    bool invertible() const { return terms_.size() == 1; }
    double sample(double u) const { return terms_[0].profile->inverse(-std::log1p(-u * reach_) / terms_[0].scale); }

private:
    std::vector<Term> terms_;
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
    CdfAndDensity cdfAndDensity(double t) const {
        double before = 0;
        for (const MajorantSegment& s : segments_) {
            if (t < s.t0) return {before / length_, 0};
            if (t <= s.t1) return {(before + t - s.t0) / length_, 1 / length_};
            before += s.t1 - s.t0;
        }
        return {1, 0};
    }

private:
    std::span<const MajorantSegment> segments_;
    double length_ = 0;
};

// The length of the stretches whose majorant may exceed the extinction by far (a minorant below it, beyond
// the bounds' own rounding): smoke's cells, where UniformCollision guards ForcedCollision.
inline double looseLength(std::span<const MajorantSegment> segments) {
    double loose = 0;
    for (const MajorantSegment& s : segments)
        if (s.minorant < s.majorant * (1 - 1e-5)) loose += s.t1 - s.t0;
    return loose;
}

// Distances over the stretches `segments` cover, drawn in proportion to 1/r² from a point beside the ray
// (equiangular sampling: Kulla & Fajardo 2012, "Importance sampling techniques for path tracing in
// participating media") times the phase function that turns the point's light toward the ray's origin and
// the segment's majorant: so the media a small source lights most, and scatters most toward the eye, get most
// draws, however short a stretch of the ray they are. In the angle φ under which the point sees t (0 at its
// foot t_c on the ray, h its distance from it), r² = h²/cos²φ and dt/dφ = h/cos²φ, so h/r² is uniform in φ;
// the phase function's cosine is −sin φ. Drawn piecewise uniform in φ, pieces of at most π/32 (one per
// segment when isotropic) weighted by the majorant times the phase at their middle.
class EquiangularCollision {
public:
    // `minDistance` > 0 keeps h off 0 (a point on the ray would make the density a delta); `phase` the
    // scattering the draws should follow (HenyeyGreenstein(0): plain equiangular sampling).
    EquiangularCollision(std::span<const MajorantSegment> segments, const Ray& ray, const dvec3& point,
                         double minDistance, const HenyeyGreenstein& phase) {
        foot_ = glm::dot(point - ray.org, ray.dir);
        h_ = std::max(glm::length(point - (ray.org + foot_ * ray.dir)), minDistance);
        const double most = phase.g() == 0 ? std::numbers::pi : std::numbers::pi / 32;
        for (const MajorantSegment& s : segments) {
            double a = angleOf(s.t0), b = angleOf(s.t1);
            int n = int(std::ceil((b - a) / most));
            for (int i = 0; i < n; ++i) {
                Piece p{a + (b - a) * i / n, a + (b - a) * (i + 1) / n};
                p.t0 = i == 0 ? s.t0 : pieces_.back().t1;
                p.t1 = i == n - 1 ? s.t1 : foot_ + h_ * std::tan(p.angle1);
                p.weight = s.majorant * phase.value(-std::sin(0.5 * (p.angle0 + p.angle1)));
                total_ += p.weight * (p.angle1 - p.angle0);
                p.cumulative = total_;
                pieces_.push_back(p);
            }
        }
    }

    // ∫ σ̄ p(−sin φ) dφ over the stretches, σ̄ the majorant, p the phase function: ∫ σ̄ p h/r² dt, about the
    // source's single scattering toward the origin per unit intensity, unattenuated, times h.
    double phaseAngle() const { return total_; }
    double distanceFromRay() const { return h_; }
    CdfAndDensity cdfAndDensity(double t) const {
        auto p = std::lower_bound(pieces_.begin(), pieces_.end(), t, [](const Piece& q, double x) { return q.t1 < x; });
        if (p == pieces_.end()) return {1, 0};
        double before = p->cumulative - p->weight * (p->angle1 - p->angle0);
        if (t < p->t0) return {before / total_, 0};
        double angle = std::clamp(std::atan((t - foot_) / h_), p->angle0, p->angle1);
        return {(before + p->weight * (angle - p->angle0)) / total_,
                p->weight / total_ * h_ / (h_ * h_ + (t - foot_) * (t - foot_))};
    }

private:
    struct Piece {
        double angle0, angle1;  // φ across the piece, and the same as distances
        double t0 = 0, t1 = 0;
        double weight = 0, cumulative = 0;  // the phase; ∫ weight dφ up to angle1
    };
    double angleOf(double t) const { return std::isfinite(t) ? std::atan((t - foot_) / h_) : std::numbers::pi / 2; }
    std::vector<Piece> pieces_;
    double foot_ = 0, h_ = 1, total_ = 0;
};

// A mixture of the samplers above, drawn by inverting its cumulative distribution Σ share_i F_i(t) (Newton's
// method, bisection where it strays or stalls): stratified numbers u then give draws stratified over the whole mixture.
// Drawn strategy by strategy instead, a strategy with a small share (a guard) would get one or two draws of
// its own and their noise, and the count each strategy got would vary with the draws.
class DistanceMixture {
public:
    using Sampler = std::variant<const ForcedCollision*, const UniformCollision*, const EquiangularCollision*,
                                 const DepthCollision*>;
    // Every component's draws lie in [lo, hi] (hi may be infinite).
    DistanceMixture(double lo, double hi) : lo_(lo), hi_(hi) {}

    void add(double share, Sampler sampler) {
        if (share > 0) components_.push_back({share, sampler});
    }
    double density(double t) const { return cdfAndDensity(t).density; }
    CdfAndDensity cdfAndDensity(double t) const {
        CdfAndDensity sum{0, 0};
        for (const Component& c : components_) {
            CdfAndDensity f = std::visit([t](auto* s) { return s->cdfAndDensity(t); }, c.sampler);
            sum.cdf += c.share * f.cdf, sum.density += c.share * f.density;
        }
        return sum;
    }
    // The distance where the cumulative distribution reaches u, in [0, 1); `from`, if known, a distance at or
    // before it (the previous draw, when drawing stratified numbers in order), where the search starts.
    double sample(double u, double from = -std::numeric_limits<double>::infinity()) const {
        double a = std::max(lo_, from), b = hi_;
        for (int i = 0; !std::isfinite(b) && i < 1100; ++i) {  // an end to bracket infinite rays with
            double far = lo_ + std::ldexp(1.0, i);
            if (cdfAndDensity(far).cdf >= u) b = far;
        }
        if (!std::isfinite(b)) return lo_;
        double x = from > lo_ ? a : 0.5 * (a + b);
        double step = b - a, stepBefore = step;
        for (int i = 0; i < 100 && b - a > 1e-13 * std::max(1.0, std::abs(x)); ++i) {
            CdfAndDensity f = cdfAndDensity(x);
            double g = f.cdf - u;
            if (std::abs(g) <= 1e-10) break;  // (t off by δ: the density at most δ·p'/p relatively off)
            (g < 0 ? a : b) = x;
            // Newton's step where it stays in the bracket and is under half the step before last; else
            // bisection: Newton's steps can cycle about a jump of the density (Numerical Recipes' rtsafe).
            double next = f.density > 0 ? x - g / f.density : a - 1;
            bool newton = next > a && next < b && std::abs(2 * g) <= std::abs(stepBefore * f.density);
            stepBefore = step;
            step = newton ? std::abs(next - x) : 0.5 * (b - a);
            x = newton ? next : 0.5 * (a + b);
        }
        return x;
    }

private:
    struct Component {
        double share;
        Sampler sampler;
    };
    double lo_, hi_;
    std::vector<Component> components_;
};

}  // namespace brume
