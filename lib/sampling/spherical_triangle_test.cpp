#include "sampling/spherical_triangle.h"

#include <gtest/gtest.h>

#include <array>
#include <numbers>

#include "sampling/testing.h"

using namespace brume;
using namespace brume::sampling::testing;

// An octant of the sphere has solid angle π/2; samples stay inside it and fill it uniformly: half fall on
// each side of the plane x = y (within 3σ of 4096 draws), and Ω·mean(z) gives ∫z dω = π/4 (the octant's
// projection on the xy plane, a quarter disk) within 0.5%.
TEST(SphericalTriangle, OctantHasSolidAngleHalfPiAndIsSampledUniformly) {
    SphericalTriangle t(dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1));
    EXPECT_NEAR(t.solidAngle(), std::numbers::pi / 2, 1e-12);
    int below = 0, n = 4096;
    double sumZ = 0;
    for (int i = 0; i < n; ++i) {
        dvec3 d = t.sample((i + 0.5) / n, ((i * 2654435761u) % n + 0.5) / n);
        ASSERT_GE(d.x, -1e-12);
        ASSERT_GE(d.y, -1e-12);
        ASSERT_GE(d.z, -1e-12);
        EXPECT_NEAR(glm::length(d), 1, 1e-12);
        below += d.x < d.y;
        sumZ += d.z;
    }
    EXPECT_NEAR(t.solidAngle() * sumZ / n, std::numbers::pi / 4, 0.005 * std::numbers::pi / 4);
    EXPECT_NEAR(below, n / 2, 3 * std::sqrt(n / 4.0));
}

// A far, small triangle: the solid angle is its area over distance squared.
TEST(SphericalTriangle, SmallTriangleSolidAngleIsAreaOverDistanceSquared) {
    SphericalTriangle t(dvec3(0), dvec3(0, 0, 100), dvec3(0.01, 0, 100), dvec3(0, 0.01, 100));
    EXPECT_NEAR(t.solidAngle(), 0.5e-4 / 1e4, 1e-6 * 0.5e-8);
}

// Draws are uniform in solid angle over the triangle, 1/Ω inside it and nothing outside (chi-square over a
// cap about it, 2×10⁵ draws in 20×40 cells: 10% off over a tenth of it fails): the octant, a long thin
// triangle, and one seen almost edge on.
TEST(SphericalTriangle, DrawsAreUniformOverItsSolidAngle) {
    const dvec3 eye(0.1, -0.2, 0.05);
    for (auto [a, b, c] : {std::array{dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)},
                           std::array{dvec3(1, 0, 2), dvec3(1.2, 0.3, 2), dvec3(-1, 1, 2.5)},
                           std::array{dvec3(-1, -1, 0.1), dvec3(1, -1, 0.1), dvec3(0, 1, 0.1)}}) {
        SphericalTriangle t(eye, a, b, c);
        dvec3 A = glm::normalize(a - eye), B = glm::normalize(b - eye), C = glm::normalize(c - eye);
        double side = glm::dot(A, glm::cross(B, C));  // the sign of the triangle's turn as seen from the eye
        auto inside = [&](const dvec3& d) {
            return glm::dot(d, glm::cross(A, B)) * side >= 0 && glm::dot(d, glm::cross(B, C)) * side >= 0 &&
                   glm::dot(d, glm::cross(C, A)) * side >= 0;
        };
        SCOPED_TRACE(t.solidAngle());
        expectSamplesFollowDensity([&](double u, double v) { return t.sample(u, v); },
                                   [&](const dvec3& d) { return inside(d) ? 1 / t.solidAngle() : 0.0; },
                                   capAround(eye, {a, b, c}, {.draws = 200'000, .rings = 20, .sectors = 40}));
    }
}
