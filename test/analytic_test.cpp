// Irradiance against closed-form answers: sphere sources, rectangle form factors, integrating spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_forms.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;
using std::numbers::pi;

// Tolerance 0.5%: cos θ varies by up to ±3% across the sphere's cone for tilted sensors; 4 × 64 stratified
// samples average that to well below 0.1%.
TEST(Analytic, SphereSourceOnPlaneGivesPiLSquaredRatioForAnyTilt) {
    TestScene t("void light lum 0 0 3 100 100 100\nlum sphere bulb 0 0 4 0 0 2 0.1\n");
    RenderSettings s = fixedSeed();
    s.sourceSubdivision = 0.01;  // 64 stratified samples of the cone per estimate
    Integrator integrator(t.render, s);
    const dvec3 center(0, 0, 2);
    for (dvec3 p : {dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0.5, -1.5, 0.3)}) {
        for (dvec3 n : {dvec3(0, 0, 1), dvec3(0.3, 0, 1), dvec3(-0.2, 0.4, 1)}) {
            double expected = sphereIrradiance(100, 0.1, center, p, n);
            EXPECT_NEAR(meanIrradiance(integrator, p, n, 4), expected, 0.005 * expected)
                << "p=" << p.x << "," << p.y << "," << p.z;
        }
    }
}

// Tolerance 1%: 64 stratified area samples per estimate, averaged over 32 estimates, leave ~0.2% noise.
TEST(Analytic, RectangleSourceMatchesCornerFormFactor) {
    TestScene t("void light panel 0 0 3 50 50 50\n"
                "panel polygon ceiling 0 0 12  0 0 2  0 3 2  2 3 2  2 0 2\n");  // faces down
    RenderSettings s = fixedSeed();
    s.sourceSubdivision = 0.01;  // as many shadow rays as the subdivision allows
    Integrator integrator(t.render, s);
    double expected = pi * 50 * cornerFormFactor(2, 3, 2);
    EXPECT_NEAR(meanIrradiance(integrator, dvec3(0, 0, 0), dvec3(0, 0, 1), 32), expected, 0.01 * expected);
    // Below the middle, four corner rectangles add up.
    double middle = 4 * pi * 50 * cornerFormFactor(1, 1.5, 2);
    EXPECT_NEAR(meanIrradiance(integrator, dvec3(1, 1.5, 0), dvec3(0, 0, 1), 32), middle, 0.01 * middle);
    // Above the panel's plane it sees only the back: nothing.
    EXPECT_EQ(meanIrradiance(integrator, dvec3(1, 1, 3), dvec3(0, 0, -1), 4), 0.0);
}

namespace {

// Inside a closed sphere of reflectance ρ lit by a small central lamp of flux Φ, every wall point receives
// E₀ = Φ/(4πR²) directly, and each interreflection multiplies the previous uniform irradiance by ρ:
// after N bounces E = E₀ (1 − ρ^(N+1)) / (1 − ρ).
struct IntegratingSphere {
    double rho, lampRadius = 0.02, lampRadiance = 1000;
    std::string text() const {
        std::ostringstream s;
        s << "void plastic wall 0 0 5 " << rho << " " << rho << " " << rho << " 0 0\n"
          << "wall bubble inside 0 0 4 0 0 0 1\n"
          << "void light lamp 0 0 3 " << lampRadiance << " " << lampRadiance << " " << lampRadiance << "\n"
          << "lamp sphere bulb 0 0 4 0 0 0 " << lampRadius << "\n";
        return s.str();
    }
    double direct() const {
        double flux = 4 * pi * lampRadius * lampRadius * pi * lampRadiance;
        return flux / (4 * pi);
    }
    double afterBounces(int n) const { return direct() * (1 - std::pow(rho, n + 1)) / (1 - rho); }
    // Mean irradiance over sensors spread on the wall, facing the centre.
    double measure(const RenderSettings& s) const {
        TestScene t(text());
        Integrator integrator(t.render, s);
        double sum = 0;
        const dvec3 dirs[] = {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-0.6, 0.8, 0}, {0, -0.6, 0.8}, {0.48, 0.6, -0.64}};
        for (int i = 0; i < 6; ++i) sum += test::irradiance(integrator, dirs[i] * (1 - 1e-4), -dirs[i], uint64_t(i)).value[0];
        return sum / 6;
    }
};

}  // namespace

// Tolerance 1.5% (the bar): 6 sensors × 2048 paths give ~0.3% noise; the lamp's shadow and its
// absorption of wall light are below 0.1%.
TEST(Analytic, IntegratingSphereMatchesAnalyticAtEachBounceCount) {
    IntegratingSphere sphere{0.5};
    RenderSettings s = fixedSeed();
    s.ambientAccuracy = 0;  // -aa 0: exactly -ab bounces
    s.ambientDivisions = 2048;
    for (int bounces : {0, 1, 2, 5}) {
        s.ambientBounces = bounces;
        double expected = sphere.afterBounces(bounces);
        EXPECT_NEAR(sphere.measure(s), expected, 0.015 * expected) << "-ab " << bounces;
    }
}

// A typical call (-ab 5 with Radiance's -aa .1, which would use its cache) reaches the all-bounce answer:
// the bounces past -ab go on by Russian roulette. Tolerance 1.5% as above.
TEST(Analytic, TypicalCallReachesTheAllBounceAnswer) {
    IntegratingSphere sphere{0.8};
    RenderSettings s = fixedSeed();
    s.ambientBounces = 5;
    s.ambientDivisions = 4096;
    double expected = sphere.direct() / (1 - 0.8);
    EXPECT_NEAR(sphere.measure(s), expected, 0.015 * expected);
    s.ambientAccuracy = 0;  // exactly five bounces: (1 − ρ⁶)/(1 − ρ) of it
    EXPECT_NEAR(sphere.measure(s), sphere.afterBounces(5), 0.015 * sphere.afterBounces(5));
}

// With Radiance's default -lr -10, a ρ = 0.8 sphere at -ab 100 must not lose the light beyond ten
// reflections (Radiance loses 8.5% there): Russian roulette keeps the estimate unbiased.
TEST(Analytic, IntegratingSphereReachesTheAllBounceLimitThroughRussianRoulette) {
    IntegratingSphere sphere{0.8};
    RenderSettings s = fixedSeed();
    s.ambientAccuracy = 0;
    s.ambientDivisions = 4096;
    s.ambientBounces = 100;
    double expected = sphere.direct() / (1 - 0.8);
    EXPECT_NEAR(sphere.measure(s), expected, 0.015 * expected);
    // A positive -lr is a hard limit: ten reflections, nothing after.
    s.maxReflections = 10;
    double capped = sphere.afterBounces(10);
    EXPECT_NEAR(sphere.measure(s), capped, 0.015 * capped);
}
