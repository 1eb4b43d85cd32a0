// What a point scatters toward the viewer of the light from one direction: a surface's lobes (f·cos θ), a
// medium's phase functions (f), each lobe that rays also sample sharing that light with them by the power
// heuristic.
#include "integrator/scatterer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrator/testing.h"
#include "material/ward.h"

using namespace brume;
using namespace brume::integrator_testing;
using std::numbers::pi;

namespace {

// A surface tilted off the axes (a normal along z would hide a swapped axis), hit 30° off its normal.
const dvec3 kNormal = glm::normalize(dvec3(0.3, -0.2, 1));
const Shading kHit = flatHit(dvec3(1, 2, 3), kNormal, -glm::normalize(kNormal + 0.577 * Frame(kNormal).s));

// Directions on both sides of the surface, some grazing.
std::vector<dvec3> someDirections() {
    Frame f(kNormal);
    std::vector<dvec3> out;
    for (double c : {0.95, 0.6, 0.2, 0.02, -0.5})
        for (double phi : {0.0, 1.0, 2.5, 4.0}) {
            double s = std::sqrt(1 - c * c);
            out.push_back(f.toWorld(dvec3(s * std::cos(phi), s * std::sin(phi), c)));
        }
    return out;
}

// The power heuristic's share of strategy a against b, written out.
double shareOf(double a, double b) { return a * a / (a * a + b * b); }

// Float precision: responses are spectra of floats (1e-20 absolute where a lobe's tail underflows them).
void expectClose(double actual, double expected) { EXPECT_NEAR(actual, expected, 1e-6 * expected + 1e-20); }

}  // namespace

// Energy: a Lambertian lobe of reflectance ρ reflects ρ of the light from the hemisphere in front, its
// transmitting twin τ into the one behind; nothing crosses to the other side. Quadrature on 200 × 400 cells:
// 1e-4 (its error is of order 1e-5 here).
TEST(Scatterer, LambertianResponseIntegratesToItsReflectance) {
    Lobes lobes;
    lobes.diffuse = Spectrum(0.6f);
    lobes.diffuseTrans = Spectrum(0.25f);
    Scatterer at(kHit, lobes);
    auto response = [&](const dvec3& l) { return double(at.response(l, 0)[0]); };
    EXPECT_NEAR(overDirections(response, kNormal, 200), 0.6, 1e-4);
    EXPECT_NEAR(overDirections(response, -kNormal, 200), 0.25, 1e-4);
    // Without the diffuse lobe (next-event estimation has it in closed form), the transmitting one is left.
    EXPECT_EQ(at.response(kNormal, 0, false)[0], 0.f);
    EXPECT_FLOAT_EQ(at.response(-kNormal, 0, false)[0], float(0.25 / pi));
    ASSERT_NE(at.lambertian(), nullptr);
    EXPECT_EQ((*at.lambertian())[0], 0.6f);
    EXPECT_FALSE(at.sampledByRays());
    EXPECT_DOUBLE_EQ(at.cosine(kNormal), 1.0);
}

// Pure-specular plastic and metal scale the diffuse part by the Fresnel estimate: no closed form then.
TEST(Scatterer, FresnelScaledDiffuseHasNoClosedForm) {
    Lobes lobes;
    lobes.diffuse = Spectrum(0.6f);
    lobes.fresnelDiffuse = true;
    Scatterer at(kHit, lobes);
    EXPECT_EQ(at.lambertian(), nullptr);
    EXPECT_FLOAT_EQ(at.response(kNormal, 0)[0], float(0.6 / pi * (1 - fresnelEstimate(1))));
}

// With lightDensity 0 (a source no ray will count) the Ward lobe takes all its light: f·cos θ. With a
// source's density, a lobe rays sample takes the power heuristic's share against the lobe's own density (the
// rays take the rest); a lobe rays do not sample still takes all of it.
TEST(Scatterer, WardResponseIsBrdfTimesCosineWeightedAgainstSampledRays) {
    Lobes ward;
    ward.glossy = Spectrum(0.3f);
    ward.alpha2 = 0.04;
    Lobes sampledWard = ward;
    sampledWard.sampleGlossy = true;
    Scatterer notSampled(kHit, ward), sampled(kHit, sampledWard);
    EXPECT_FALSE(notSampled.sampledByRays());
    EXPECT_TRUE(sampled.sampledByRays());
    dvec3 wo = -kHit.dir;
    for (const dvec3& l : someDirections()) {
        double cosL = glm::dot(kNormal, l);
        double f = cosL > 0 ? 0.3 * wardBrdf(wo, l, kNormal, 0.04) * cosL : 0.0;
        expectClose(sampled.response(l, 0)[0], f);
        for (double lightDensity : {0.5, 20.0}) {
            double rayDensity = wardPdf(wo, l, kNormal, 0.04);
            expectClose(sampled.response(l, lightDensity)[0], f * shareOf(lightDensity, rayDensity));
            expectClose(notSampled.response(l, lightDensity)[0], f);
        }
    }
}

// A medium's response is its phase mixture's, Σ coefficient × HG(g, cos θ), θ between the light's way in (−l)
// and the ray's way back (−dir); over the whole sphere it integrates to Σ coefficient (quadrature on 400 ×
// 800 cells: 1e-4). A medium has no normal (cosine 0) and no Lambertian lobe.
TEST(Scatterer, MediumResponseIsThePhaseMixtures) {
    PhaseMixture phase;
    phase.add(Spectrum(0.3f), 0.6);
    phase.add(Spectrum(0.2f), -0.3);
    const dvec3 dir = glm::normalize(dvec3(1, 2, -0.5));
    Scatterer at(dvec3(0), dir, phase, false);
    EXPECT_EQ(at.surface(), nullptr);
    EXPECT_EQ(at.lambertian(), nullptr);
    EXPECT_EQ(at.cosine(dir), 0.0);
    auto hg = [](double g, double c) { return (1 - g * g) / (4 * pi * std::pow(1 + g * g - 2 * g * c, 1.5)); };
    for (const dvec3& l : someDirections()) {
        double c = glm::dot(l, dir);
        double expected = 0.3 * hg(0.6, c) + 0.2 * hg(-0.3, c);
        expectClose(at.response(l, 0)[0], expected);
        expectClose(at.response(l, 5.0)[0], expected);  // not sampled by rays: all of it
    }
    auto response = [&](const dvec3& l) { return double(at.response(l, 0)[0]); };
    EXPECT_NEAR(overDirections(response, dir, 400, true), 0.5, 1e-4);
    // Forward scattering dominates: light arriving from ahead of the ray (l = dir) goes on toward its origin.
    EXPECT_GT(at.response(dir, 0)[0], 3 * at.response(-dir, 0)[0]);
}

// Where rays also sample the phase functions, a source's light is shared with them by the power heuristic
// against the mixture's density.
TEST(Scatterer, SampledMediumSharesWithRaysByThePowerHeuristic) {
    PhaseMixture phase;
    phase.add(Spectrum(1.f), 0.4);
    const dvec3 dir(0, 0, 1);
    Scatterer sampled(dvec3(0), dir, phase, true), alone(dvec3(0), dir, phase, false);
    EXPECT_TRUE(sampled.sampledByRays());
    EXPECT_FALSE(alone.sampledByRays());
    for (const dvec3& l : someDirections()) {
        double f = alone.response(l, 0)[0], rayDensity = phase.pdf(dir, l);
        expectClose(sampled.response(l, 0)[0], f);
        expectClose(sampled.response(l, 2.0)[0], f * shareOf(2.0, rayDensity));
    }
}
