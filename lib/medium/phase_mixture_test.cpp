#include "medium/phase_mixture.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;

namespace {

// At a point found by a ray along `dir`, the mixture's draws follow its density (chi-square: 4×10⁵ draws in
// 40×80 cells about `dir`: 9% off over a tenth of the draws fails), and each draw's own pdf is pdf() of its
// direction.
void expectMixtureDrawsFollowItsDensity(const PhaseMixture& mixture, const dvec3& dir) {
    auto sample = [&](double u, double v) -> std::optional<sampling::testing::WeighedDraw> {
        std::optional<PhaseSample> d = mixture.sample(dir, u, v);
        if (!d) return std::nullopt;
        return sampling::testing::WeighedDraw{d->wi, d->pdf};
    };
    sampling::testing::expectDrawsFollowTheirDensity(sample, [&](const dvec3& wi) { return mixture.pdf(dir, wi); },
                                                     {.draws = 400'000, .rings = 40, .sectors = 80, .axis = dir});
}

}  // namespace

// A forward and a backward lobe, and three lobes whose coefficients differ across bands (a lobe is drawn by
// its coefficient's brightness): draws follow the mixture of the lobes weighted by those brightnesses.
TEST(PhaseMixture, DrawsFollowTheMixtureOfItsLobes) {
    const dvec3 dir = glm::normalize(dvec3(-0.2, 0.5, 0.6));
    PhaseMixture twoLobes;
    twoLobes.add(Spectrum(0.3f), 0.8);
    twoLobes.add(Spectrum(0.1f), -0.5);
    expectMixtureDrawsFollowItsDensity(twoLobes, dir);
    PhaseMixture threeLobes;
    threeLobes.add(Spectrum(0.5f, 0.2f, 0.1f), 0.9);
    threeLobes.add(Spectrum(0.05f, 0.1f, 0.4f), 0.0);
    threeLobes.add(Spectrum(0.2f, 0.2f, 0.2f), -0.3);
    expectMixtureDrawsFollowItsDensity(threeLobes, dir);
}
