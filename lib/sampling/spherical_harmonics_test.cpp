#include "sampling/spherical_harmonics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "medium/henyey_greenstein.h"

using namespace brume;
using std::numbers::pi;

namespace {

// ∫ f(ω) dω over the sphere by the midpoint rule, n rows of θ by 2n columns of φ (error of order 1/n²).
template <class F>
double overSphere(F&& f, int n = 400) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        double theta = pi * (i + 0.5) / n;
        for (int j = 0; j < 2 * n; ++j) {
            double phi = pi * (j + 0.5) / n;
            dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            sum += f(d) * std::sin(theta);
        }
    }
    return sum * (pi / n) * (pi / n);
}

}  // namespace

// The nine functions are orthonormal over the sphere (quadrature error ~1e-5 at n = 400).
TEST(SphericalHarmonics, AreOrthonormal) {
    for (int a = 0; a < kShCount; ++a)
        for (int b = a; b < kShCount; ++b) {
            double dot = overSphere([&](const dvec3& d) { auto y = shBasis(d); return y[a] * y[b]; });
            EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 1e-4) << a << " " << b;
        }
}

// Funk–Hecke: ∫ p_HG(ω·d) Y_k(ω) dω = g^l Y_k(d), which VolumeZones::scattered relies on; for forward,
// backward and isotropic lobes (a wrong power of g for an order would be off by ~10% of Y_k).
TEST(SphericalHarmonics, AHenyeyGreensteinLobeScalesOrderLByGToTheL) {
    const dvec3 d = glm::normalize(dvec3(0.3, -0.5, 0.8));
    for (double g : {0.0, 0.6, -0.3}) {
        HenyeyGreenstein phase(g);
        auto y = shBasis(d);
        for (int k = 0; k < kShCount; ++k) {
            double convolved = overSphere([&](const dvec3& w) { return phase.value(glm::dot(w, d)) * shBasis(w)[k]; });
            EXPECT_NEAR(convolved, std::pow(g, shOrder(k)) * y[k], 2e-4) << "g " << g << " k " << k;
        }
    }
}
