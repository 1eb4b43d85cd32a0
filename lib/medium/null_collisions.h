// Tracking through heterogeneous media by null collisions: the extinction σ_t(t) along a ray is topped up to a
// majorant σ̄ ≥ σ_t by fictitious particles that do nothing, so that free flights are sampled in closed form
// with σ̄ and each tentative collision is a real one or a null one. Unbiased for any majorant; the closer σ̄
// to σ_t, the fewer tentative collisions. Extinction is a spectrum (one value per band); the majorant is
// one number over all bands.
#pragma once
#include <cmath>
#include <optional>

#include "sampling/random.h"
#include "spectrum/spectrum.h"

namespace brume {

// A stretch [t0, t1] of a ray over which σ̄ ≥ σ_t(t) in every band; `minorant` ≤ σ_t(t) in the band σ̄ bounds
// (0 when unknown): where they are equal, σ̄ is the extinction itself.
struct MajorantSegment {
    double t0, t1, majorant, minorant = 0;
};

// Calls f(t, majorant) at each tentative collision along `segments` (free flights of rate σ̄ in each, which
// restart at each segment's start: exponential flights have no memory) until f returns false; returns whether
// the walk got past the last segment.
template <class Segments, class F>
bool forEachTentativeCollision(const Segments& segments, Random& random, const F& f) {
    for (const MajorantSegment& s : segments) {
        if (!(s.majorant > 0)) continue;
        for (double t = s.t0;;) {
            t -= std::log1p(-random.uniform()) / s.majorant;
            if (t >= s.t1) break;
            if (!f(t, s.majorant)) return false;
        }
    }
    return true;
}

// The first real collision of delta tracking (Woodcock et al. 1965) along `segments`, for a path whose bands
// carry `weight`, with spectral tracking's probabilities (Kutz, Habel, Li and Novák 2017): a tentative
// collision is real with probability ∝ mean(weight·σ_t), null ∝ mean(weight·(σ̄ − σ_t)), and the weight is
// divided by that probability, so every band stays unbiased whatever its σ_t. Returns the collision's t
// with `weight` updated (times σ_t/σ̄ over the probability: the caller multiplies by the albedo), or
// nullopt past the last segment, `weight` updated for the way through.
template <class Segments, class Extinction>
std::optional<double> deltaTracking(const Segments& segments, const Extinction& extinction, Spectrum& weight,
                                    Random& random) {
    std::optional<double> collision;
    forEachTentativeCollision(segments, random, [&](double t, double majorant) {
        Spectrum sigma = extinction(t);
        double real = 0, null = 0;
        for (int i = 0; i < weight.size(); ++i) {
            double a = std::abs(weight[i]), sigmaT = std::min(double(sigma[i]), majorant);
            real += a * sigmaT, null += a * (majorant - sigmaT);
        }
        if (!(real + null > 0)) return false;  // nothing left to carry
        double pReal = real / (real + null);
        bool isReal = random.uniform() < pReal;
        double p = isReal ? pReal : 1 - pReal;
        for (int i = 0; i < weight.size(); ++i) {
            double sigmaT = std::min(double(sigma[i]), majorant);
            weight[i] *= float((isReal ? sigmaT : majorant - sigmaT) / (majorant * p));
        }
        if (isReal) collision = t;
        return !isReal;
    });
    return collision;
}

}  // namespace brume
