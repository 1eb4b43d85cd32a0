#include "sampling/polygon_points.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/polygon.h"

namespace brume {
namespace {

Polygon polygon(std::vector<dvec3> vertices) {
    std::string why;
    Polygon p = *makePolygon(std::move(vertices), why);
    p.triangles = triangulate(p);
    return p;
}

// Draws from uniform (u, v) against the uniform density over an L-shaped (concave) polygon of three unit
// squares in the plane z = 1: a chi-square over the 27 cells of a third of a unit that the L covers (cells of
// its bounding square outside it must stay empty).
TEST(PolygonPoints, AreUniformByArea) {
    Polygon p = polygon({{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}});
    PolygonPoints points(p);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u01(0, 1);
    const int cells = 6, draws = 270000;
    std::vector<int> count(cells * cells);
    for (int i = 0; i < draws; ++i) {
        dvec3 q = points.at(u01(rng), u01(rng));
        ASSERT_NEAR(q.z, 1, 1e-12);
        ++count[size_t(std::clamp(int(q.x * 3), 0, cells - 1) + cells * std::clamp(int(q.y * 3), 0, cells - 1))];
    }
    double chi2 = 0, expected = draws / 27.0;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (i >= 3 && j >= 3) {
                EXPECT_EQ(count[size_t(i + cells * j)], 0);
                continue;
            }
            double d = count[size_t(i + cells * j)] - expected;
            chi2 += d * d / expected;
        }
    EXPECT_LT(chi2, 54.1);  // chi-square with 26 degrees of freedom: p = 0.001
}

}  // namespace
}  // namespace brume
