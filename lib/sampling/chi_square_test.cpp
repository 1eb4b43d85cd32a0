// The chi-square harness (testing.h) itself: its p-value, and that it accepts draws with their own density and
// rejects the same draws with a density slightly off, a density that loses mass they do not (or the reverse),
// and draws where the density is 0. A harness that cannot fail proves nothing about the samplers it passes.
#include "sampling/testing.h"

#include <gtest/gtest.h>

#include "medium/henyey_greenstein.h"

using namespace brume;
using namespace brume::sampling::testing;
using std::numbers::pi;

namespace {

std::optional<dvec3> uniformSphere(double u, double v) { return uniformCone(u, v, 2); }
std::optional<dvec3> cosine(double u, double v) { return cosineHemisphere(u, v); }
double cosineDensity(const dvec3& d) { return std::max(0.0, d.z) / pi; }

// 2×10⁵ draws in 20×40 cells: 250 a cell on average, as most samplers' tests use.
const DirectionOptions kSmall{.draws = 200'000, .rings = 20, .sectors = 40};

// Q(n, x) for whole n: e^{−x} Σ_{k<n} x^k/k! (the Poisson distribution's tail), summed in logarithms.
double poissonTail(int n, double x) {
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += std::exp(-x + k * std::log(x) - std::lgamma(k + 1.0));
    return sum;
}

}  // namespace

// Against closed forms (Q(1, x) = e^{−x}, Q(½, x) = erfc √x, whole a: the Poisson tail) on both sides of
// x = a + 1, where the series gives way to the continued fraction, at the degrees of freedom the tests use
// (a up to 2500), and at the 1% point of 100 degrees of freedom (135.807, from tables).
TEST(ChiSquare, PValueIsTheRegularisedUpperIncompleteGamma) {
    for (double x : {0.1, 1.5, 7.0}) {
        EXPECT_NEAR(upperGammaQ(1, x), std::exp(-x), 1e-13);
        EXPECT_NEAR(upperGammaQ(0.5, x), std::erfc(std::sqrt(x)), 1e-13);
    }
    for (int n : {3, 40, 400, 2500})
        for (double x : {0.7 * n, 0.98 * n, 1.1 * n, 1.3 * n}) {
            double expected = poissonTail(n, x);
            EXPECT_NEAR(upperGammaQ(n, x), expected, 1e-10 + 1e-9 * expected) << "a " << n << " x " << x;
        }
    EXPECT_NEAR(upperGammaQ(50, 135.807 / 2), 0.01, 1e-5);
}

// The significance each test uses: Šidák's correction of 1% over the suite.
TEST(ChiSquare, EachTestRejectsWithTheSuitesSignificanceSplitBySidak) {
    EXPECT_NEAR(1 - std::pow(1 - testSignificance(), kTestsInSuite), kSuiteSignificance, 1e-12);
}

// Uniform draws over the sphere and cosine-weighted ones over the hemisphere, each with its own density: the
// densities integrate to 1 and every draw gives a sample.
TEST(ChiSquare, AcceptsDrawsWithTheirOwnDensity) {
    ChiSquareResult sphere = chiSquare(uniformSphere, [](const dvec3&) { return 1 / (4 * pi); });
    EXPECT_TRUE(sphere.accepted) << sphere.report;
    EXPECT_NEAR(sphere.densityIntegral, 1, 1e-9);
    EXPECT_EQ(sphere.sampledFraction, 1);
    ChiSquareResult hemisphere = chiSquare(cosine, cosineDensity);
    EXPECT_TRUE(hemisphere.accepted) << hemisphere.report;
    EXPECT_NEAR(hemisphere.densityIntegral, 1, 1e-6);
}

// Draws the sampler drops where its density is 0 are mass both agree is lost: cosine-weighted draws kept in the
// wedge 0.5 < φ ≤ π, which holds (π − 0.5)/2π of them. The density integrates to that within the integration's
// tolerance, and the share of draws kept is within 4 standard errors of it.
TEST(ChiSquare, AcceptsMassLostWhereTheDensityIsZero) {
    auto inWedge = [](const dvec3& d) { return std::atan2(d.y, d.x) > 0.5; };
    auto sample = [&](double u, double v) -> std::optional<dvec3> {
        dvec3 d = cosineHemisphere(u, v);
        return inWedge(d) ? std::optional(d) : std::nullopt;
    };
    ChiSquareResult r = chiSquare(
        sample, [&](const dvec3& d) { return inWedge(d) ? cosineDensity(d) : 0.0; }, kSmall);
    EXPECT_TRUE(r.accepted) << r.report;
    const double share = (pi - 0.5) / (2 * pi);
    EXPECT_NEAR(r.densityIntegral, share, 1e-4);
    EXPECT_NEAR(r.sampledFraction, share, 4 * std::sqrt(share * (1 - share) / kSmall.draws));
}

// Cosine-weighted draws reported with the uniform hemisphere's density 1/2π.
TEST(ChiSquare, RejectsCosineDrawsReportedAsUniform) {
    auto uniformHemisphere = [](const dvec3& d) { return d.z > 0 ? 1 / (2 * pi) : 0.0; };
    ChiSquareResult r = chiSquare(cosine, uniformHemisphere, kSmall);
    EXPECT_FALSE(r.accepted) << r.report;
    EXPECT_NE(r.report.find("worst cells"), std::string::npos);
}

// Henyey–Greenstein draws for g = 0.6 reported with the density for g = 0.62, which differs by 12% at most.
TEST(ChiSquare, RejectsHenyeyGreensteinDrawsReportedWithASlightlyDifferentG) {
    HenyeyGreenstein drawn(0.6), reported(0.62);
    const dvec3 axis = glm::normalize(dvec3(0.2, -0.5, 0.7));
    auto sample = [&](double u, double v) { return drawn.sample(axis, u, v); };
    auto density = [&](double g) {
        return [g, &axis](const dvec3& d) { return HenyeyGreenstein(g).value(glm::dot(d, axis)); };
    };
    DirectionOptions about = kSmall;
    about.axis = axis;
    EXPECT_TRUE(chiSquare(sample, density(0.6), about).accepted);
    ChiSquareResult r = chiSquare(sample, density(0.62), about);
    EXPECT_FALSE(r.accepted) << r.report;
}

// A sampler that drops 1% of its draws while its density claims them, and one that drops none while its density
// claims 1% lost.
TEST(ChiSquare, RejectsLostMassTheDensityDoesNotReport) {
    auto dropping = [](double u, double v) -> std::optional<dvec3> {
        return u < 0.01 ? std::nullopt : std::optional(cosineHemisphere(u, v));
    };
    EXPECT_FALSE(chiSquare(dropping, cosineDensity, kSmall).accepted);
    auto claimingLoss = [](const dvec3& d) { return 0.99 * cosineDensity(d); };
    ChiSquareResult r = chiSquare(cosine, claimingLoss, kSmall);
    EXPECT_FALSE(r.accepted) << r.report;
    EXPECT_NE(r.report.find("lost"), std::string::npos);
}

// Draws in a wedge where the density says none can fall.
TEST(ChiSquare, RejectsDrawsWhereTheDensityIsZero) {
    auto zeroInAWedge = [](const dvec3& d) { return std::atan2(d.y, d.x) > 0.1 ? cosineDensity(d) : 0.0; };
    ChiSquareResult r = chiSquare(cosine, zeroInAWedge, kSmall);
    EXPECT_FALSE(r.accepted);
    EXPECT_NE(r.report.find("where the density integrates to 0"), std::string::npos) << r.report;
}

// Distances: exponential free flights of rate 2 (t = −ln(1 − u)/2) on [0, 3], beyond which e^{−6} of them go
// (counted as lost); accepted with density 2e^{−2t}, rejected with rate 2.05.
TEST(ChiSquare, DistancesAreTestedOnAnInterval) {
    auto flight = [](double u) -> std::optional<double> { return -std::log1p(-u) / 2; };
    auto exponential = [](double rate) { return [rate](double t) { return rate * std::exp(-rate * t); }; };
    DistanceOptions interval{.lo = 0, .hi = 3};
    ChiSquareResult r = chiSquare(flight, exponential(2), interval);
    EXPECT_TRUE(r.accepted) << r.report;
    EXPECT_NEAR(r.densityIntegral, 1 - std::exp(-6), 1e-9);
    EXPECT_FALSE(chiSquare(flight, exponential(2.05), interval).accepted);
}
