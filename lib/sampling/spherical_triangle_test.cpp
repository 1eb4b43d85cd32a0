#include "sampling/spherical_triangle.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace brume;

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
