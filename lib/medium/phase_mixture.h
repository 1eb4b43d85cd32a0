// Light scattered at a point of a medium where media overlap (a homogeneous medium, smoke grids): a mixture of
// Henyey–Greenstein lobes, each weighted by a coefficient per band (its scattering coefficient times whatever
// the estimator carries). Next-event estimation asks its response toward a source; sampled rays draw from it.
//
// Directions: `dir` is the direction of the ray that found the scattering point (the light scattered toward
// its origin leaves along −dir); `wi` points toward where the light arrives from. The angle between the
// directions light travels before and after scattering is that between wi and dir.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>

#include "medium/henyey_greenstein.h"
#include "spectrum/spectrum.h"

namespace brume {

// A direction drawn from a phase mixture: its weight is response/pdf.
struct PhaseSample {
    dvec3 wi;
    Spectrum weight;
    double pdf;  // solid-angle density
};

class PhaseMixture {
public:
    static constexpr int kMaxComponents = 9;

    void add(const Spectrum& coefficient, double g) {
        float share = brightness(coefficient);
        if (!(share > 0) || count_ == kMaxComponents) return;
        components_[count_++] = {coefficient, HenyeyGreenstein(g), share};
        total_ += share;
    }
    bool empty() const { return count_ == 0; }
    // The sum of the coefficients: what the lobe scatters in all (the phase functions integrate to 1).
    Spectrum coefficient() const {
        Spectrum sum(0.f);
        for (int j = 0; j < count_; ++j) sum += components_[j].coefficient;
        return sum;
    }

    // Calls f(coefficient, g) for each lobe.
    template <class F>
    void forEachLobe(F&& f) const {
        for (int j = 0; j < count_; ++j) f(components_[j].coefficient, components_[j].phase.g());
    }

    // Σ coefficient × p(θ), per steradian.
    Spectrum response(const dvec3& dir, const dvec3& wi) const {
        double c = glm::dot(wi, dir);
        Spectrum f(0.f);
        for (int j = 0; j < count_; ++j) f += components_[j].coefficient * float(components_[j].phase.value(c));
        return f;
    }
    // The density of sample()'s draws: the lobes' densities weighted by their shares.
    double pdf(const dvec3& dir, const dvec3& wi) const {
        double c = glm::dot(wi, dir), p = 0;
        for (int j = 0; j < count_; ++j) p += components_[j].share * components_[j].phase.value(c);
        return total_ > 0 ? p / total_ : 0;
    }
    // One lobe chosen by its share (by u, which is then reused), then its direction; weight = response / pdf
    // of the whole mixture.
    std::optional<PhaseSample> sample(const dvec3& dir, double u, double v) const {
        if (count_ == 0) return std::nullopt;
        double pick = u * total_;
        int j = 0;
        while (j + 1 < count_ && pick >= components_[j].share) pick -= components_[j++].share;
        double reused = std::clamp(pick / components_[j].share, 0.0, std::nextafter(1.0, 0.0));
        dvec3 wi = components_[j].phase.sample(dir, reused, v);
        double p = pdf(dir, wi);
        if (!(p > 0)) return std::nullopt;
        return PhaseSample{wi, response(dir, wi) * float(1 / p), p};
    }

private:
    struct Component {
        Spectrum coefficient;
        HenyeyGreenstein phase{0};
        float share;
    };
    Component components_[kMaxComponents];
    int count_ = 0;
    float total_ = 0;
};

}  // namespace brume
