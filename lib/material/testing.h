// For the material unit tests: a GeneralLobe's draws against the density it reports.
#pragma once
#include <gtest/gtest.h>

#include "material/material.h"
#include "sampling/testing.h"

namespace brume::material::testing {

// At hit `s` the lobe's draws follow pdf(), and each draw's own pdf is pdf() of its direction
// (sampling/testing.h's expectDrawsFollowTheirDensity).
inline void expectDrawsFollowPdf(const GeneralLobe& lobe, const Shading& s,
                                 const sampling::testing::DirectionOptions& options = {}) {
    auto sample = [&](double u, double v) -> std::optional<sampling::testing::WeighedDraw> {
        std::optional<LobeSample> d = lobe.sample(s, u, v);
        if (!d) return std::nullopt;
        return sampling::testing::WeighedDraw{d->dir, d->pdf};
    };
    sampling::testing::expectDrawsFollowTheirDensity(sample, [&](const dvec3& wi) { return lobe.pdf(s, wi); },
                                                     options);
}

}  // namespace brume::material::testing
