// For the material unit tests: a GeneralLobe's draws against the density it reports.
#pragma once
#include <gtest/gtest.h>

#include "material/material.h"
#include "sampling/testing.h"

namespace brume::material::testing {

// At hit `s` the lobe's draws follow pdf() (chi-square, sampling/testing.h), and each draw's own pdf is pdf() of
// its direction: the integrator weighs a sampled ray by the one and a light sample by the other (MIS), so
// either off biases the light it finds.
inline void expectDrawsFollowPdf(const GeneralLobe& lobe, const Shading& s,
                                 const sampling::testing::DirectionOptions& options = {}) {
    int disagreeing = 0;
    auto sample = [&](double u, double v) -> std::optional<dvec3> {
        std::optional<LobeSample> d = lobe.sample(s, u, v);
        if (d && !(std::abs(d->pdf - lobe.pdf(s, d->dir)) <= 1e-9 * d->pdf)) ++disagreeing;
        return d ? std::optional(d->dir) : std::nullopt;
    };
    auto pdf = [&](const dvec3& wi) { return lobe.pdf(s, wi); };
    sampling::testing::expectSamplesFollowDensity(sample, pdf, options);
    EXPECT_EQ(disagreeing, 0) << "draws whose own pdf is not pdf() of their direction";
}

}  // namespace brume::material::testing
