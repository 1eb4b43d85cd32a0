// Light scattered at a point of a medium where media overlap (a homogeneous medium, smoke grids): a mixture of
// Henyey–Greenstein lobes, each weighted by a coefficient per band (its scattering coefficient times whatever
// the estimator carries). To the integrator it is a lobe like a surface's: next-event estimation asks its
// response, sampled rays draw from it.
#pragma once
#include <algorithm>

#include "material/material.h"
#include "medium/henyey_greenstein.h"

namespace brume {

class PhaseMixture : public GeneralLobe {
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

    // wi points toward where the light comes from; s.dir is the direction the light leaves in, reversed.
    Spectrum response(const Shading& s, const dvec3& wi) const override {
        double c = glm::dot(wi, s.dir);
        Spectrum f(0.f);
        for (int j = 0; j < count_; ++j) f += components_[j].coefficient * float(components_[j].phase.value(c));
        return f;
    }
    double pdf(const Shading& s, const dvec3& wi) const override {
        double c = glm::dot(wi, s.dir), p = 0;
        for (int j = 0; j < count_; ++j) p += components_[j].share * components_[j].phase.value(c);
        return total_ > 0 ? p / total_ : 0;
    }
    // One lobe chosen by its share, then its direction; weight = response / pdf of the whole mixture.
    std::optional<LobeSample> sample(const Shading& s, double u, double v) const override {
        if (count_ == 0) return std::nullopt;
        double pick = u * total_;
        int j = 0;
        while (j + 1 < count_ && pick >= components_[j].share) pick -= components_[j++].share;
        double reused = std::clamp(pick / components_[j].share, 0.0, std::nextafter(1.0, 0.0));
        dvec3 wi = components_[j].phase.sample(s.dir, reused, v);
        double p = pdf(s, wi);
        if (!(p > 0)) return std::nullopt;
        return LobeSample{wi, response(s, wi) * float(1 / p), p, true};
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
