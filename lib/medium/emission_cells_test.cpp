// Flames' light sampled by next-event estimation: points drawn from the emission cells, seen as directions
// from a point, must follow the density per steradian the cells report (it weighs them against rays drawn from
// lobes, and divides their light), from outside the flames and from inside them; the density integrates to 1
// over the sphere (no direction's mass lost or invented) and is 0 where no cell glows.
#include "medium/emission_cells.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/testing.h"

using namespace brume;

namespace {

// A flame in a 1 × 2 × 1 m box: a smooth plume brightest low down, a hot core, and a cold top half.
double plume(const dvec3& p) {
    if (p.y > 1.5) return 0;
    double r2 = (p.x - 0.5) * (p.x - 0.5) + (p.z - 0.5) * (p.z - 0.5);
    double core = r2 < 0.01 && p.y < 0.5 ? 20 : 0;
    return std::exp(-4 * r2) * (2 - p.y) + core;
}

const Bounds3 kBox{dvec3(0, 0, 0), dvec3(1, 2, 1)};

// Directions from `eye` toward the cells' draws: (u, v) choose the cell and one coordinate, a stream of its own
// the other two.
sampling::testing::DirectionSampler towardDraws(const EmissionCells& cells, const dvec3& eye, Random& extra) {
    return [&cells, eye, &extra](double u, double v) -> std::optional<dvec3> {
        dvec3 d = cells.sample(u, v, extra.uniform(), extra.uniform()) - eye;
        return glm::length(d) > 0 ? std::optional(glm::normalize(d)) : std::nullopt;
    };
}

TEST(EmissionCells, DirectionsFromOutsideFollowTheirDensity) {
    EmissionCells cells(kBox, 0.25, plume);
    ASSERT_FALSE(cells.empty());
    EXPECT_EQ(cells.resolution(), glm::ivec3(4, 8, 4));
    const dvec3 eye(2.5, 0.7, 1.8);
    Random extra(3);
    std::vector<dvec3> corners;
    for (int i = 0; i < 8; ++i) corners.push_back(dvec3(i & 1, 2 * ((i >> 1) & 1), i >> 2));
    sampling::testing::expectSamplesFollowDensity(
        towardDraws(cells, eye, extra), [&](const dvec3& d) { return cells.directionDensity(eye, d); },
        sampling::testing::capAround(eye, corners, {.draws = 400'000, .rings = 40, .sectors = 80}));
}

TEST(EmissionCells, DirectionsFromInsideFollowTheirDensity) {
    EmissionCells cells(kBox, 0.25, plume);
    const dvec3 eye(0.6, 0.4, 0.45);  // in the plume, beside the core
    Random extra(5);
    sampling::testing::expectSamplesFollowDensity(towardDraws(cells, eye, extra),
                                                  [&](const dvec3& d) { return cells.directionDensity(eye, d); },
                                                  {.draws = 400'000, .rings = 40, .sectors = 80});
}

// The points' density per volume: the cold top half never drawn and of density 0; the hot core's cells far
// denser than the edge's.
TEST(EmissionCells, ColdCellsAreNeverDrawn) {
    EmissionCells cells(kBox, 0.25, plume);
    Random random(9);
    for (int i = 0; i < 100000; ++i) {
        dvec3 p = cells.sample(random.uniform(), random.uniform(), random.uniform(), random.uniform());
        ASSERT_LE(p.y, 1.5) << i;
        ASSERT_GT(cells.density(p), 0) << i;
    }
    EXPECT_EQ(cells.density(dvec3(0.5, 1.8, 0.5)), 0);
    EXPECT_EQ(cells.density(dvec3(0.5, 0.5, -0.1)), 0);
    EXPECT_GT(cells.density(dvec3(0.5, 0.2, 0.5)), 5 * cells.density(dvec3(0.1, 0.2, 0.1)));
    EXPECT_EQ(cells.directionDensity(dvec3(0.5, 3, 0.5), dvec3(0, 1, 0)), 0);  // looking away
}

TEST(EmissionCells, NoGlowNoCells) {
    EXPECT_TRUE(EmissionCells(kBox, 0.25, [](const dvec3&) { return 0.0; }).empty());
    EXPECT_TRUE(EmissionCells(Bounds3{}, 0.25, plume).empty());
    EmissionCells none;
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(none.directionDensity(dvec3(0), dvec3(1, 0, 0)), 0);
}

// However fine the cells asked for, at most kMaxCells.
TEST(EmissionCells, CellsAreBounded) {
    EmissionCells cells(Bounds3{dvec3(0), dvec3(100, 10, 50)}, 0.01, [](const dvec3&) { return 1.0; });
    glm::ivec3 n = cells.resolution();
    EXPECT_LE(n.x * n.y * n.z, EmissionCells::kMaxCells);
    EXPECT_GT(n.x * n.y * n.z, EmissionCells::kMaxCells / 3);
    EXPECT_NEAR(cells.power(), 100 * 10 * 50, 1e-6 * 100 * 10 * 50);
}

}  // namespace
