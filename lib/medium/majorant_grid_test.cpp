#include "medium/majorant_grid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "medium/testing.h"
#include "sampling/random.h"
#include "util/error.h"

namespace brume {
namespace {

using namespace medium::testing;

struct Segment {
    double t0, t1, majorant, minorant;
};

std::vector<Segment> walk(const MajorantGrid& grid, const Ray& ray, double tmin, double tmax) {
    std::vector<Segment> segments;
    grid.forEachBound(ray, tmin, tmax, [&](double t0, double t1, double most, double least) {
        segments.push_back({t0, t1, most, least});
        return true;
    });
    return segments;
}

// The majorants along a walk, consecutive equal ones once, each with where it starts.
std::vector<std::pair<double, double>> majorantSteps(const std::vector<Segment>& segments) {
    std::vector<std::pair<double, double>> steps;
    for (const Segment& s : segments)
        if (steps.empty() || steps.back().second != s.majorant) steps.push_back({s.t0, s.majorant});
    return steps;
}

// The segments tile [t0, t1] in order, each of positive length.
void expectTiling(const std::vector<Segment>& segments, double t0, double t1) {
    ASSERT_FALSE(segments.empty());
    EXPECT_EQ(segments.front().t0, t0);
    EXPECT_EQ(segments.back().t1, t1);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        EXPECT_LT(segments[i].t0, segments[i].t1);
        if (i == 0) continue;
        EXPECT_EQ(segments[i].t0, segments[i - 1].t1);
        EXPECT_TRUE(segments[i].majorant != segments[i - 1].majorant ||  // equal neighbours are merged
                    segments[i].minorant != segments[i - 1].minorant);
    }
}

dvec3 uniformIn(const Bounds3& b, Random& random) {
    return b.lo + dvec3(random.uniform(), random.uniform(), random.uniform()) * (b.hi - b.lo);
}

// Random points and random rays with random samples along their segments: the majorant is never below the
// interpolated density, the minorant never above it.
void expectBounds(const DensityGrid& density, const MajorantGrid& majorant, int samples) {
    Random random(7);
    Bounds3 b = density.bounds();
    for (int i = 0; i < samples; ++i) {
        const dvec3 p = uniformIn(b, random);
        ASSERT_GE(majorant.majorant(p), density.density(p)) << p.x << " " << p.y << " " << p.z;
        ASSERT_LE(majorant.minorant(p), density.density(p)) << p.x << " " << p.y << " " << p.z;
    }
    for (int i = 0; i < samples / 100; ++i) {
        const dvec3 o = uniformIn(b, random), d = glm::normalize(uniformIn(b, random) - o);
        majorant.forEachBound(Ray(o, d), -1e9, 1e9, [&](double t0, double t1, double most, double least) {
            for (int k = 0; k < 10; ++k) {
                const dvec3 p = o + (t0 + random.uniform() * (t1 - t0)) * d;
                EXPECT_GE(most, density.density(p));
                EXPECT_LE(least, density.density(p));
            }
            return true;
        });
    }
}

TEST(MajorantGrid, BoxMajorantIsItsDensityInsideAndZeroOutside) {
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {39, 39, 39}, 2.0f, 0.1));
    MajorantGrid grid(box);
    EXPECT_EQ(grid.resolution(), glm::ivec3(6));  // 41 voxels of support, cells of 8
    EXPECT_EQ(grid.majorant({2, 2, 2}), 2.0);
    EXPECT_EQ(grid.majorant({-0.05, 2, 2}), 2.0);
    EXPECT_EQ(grid.majorant({5, 2, 2}), 0.0);
    expectBounds(box, grid, 100000);
}

// voxelsPerCell 0: one cell, fitted to the support of a long box (voxels −1 … 40 by −1 … 10 by −1 … 5), with
// the largest density; rays beside the box (in the cube its longest side would make) give no segment.
TEST(MajorantGrid, OneCellIsTheGridsBoxAlone) {
    auto grid = boxGrid({0, 0, 0}, {39, 9, 4}, 1.0f);
    grid->tree().setValue({20, 5, 2}, 3.0f);
    DensityGrid box = densityOf(grid);
    MajorantGrid one(box, 0);
    EXPECT_EQ(one.resolution(), glm::ivec3(1));
    EXPECT_EQ(one.majorant({0, 0, 0}), 3.0);
    EXPECT_EQ(one.majorant({39.9, 9.9, 4.9}), 3.0);
    EXPECT_EQ(one.majorant({20, 12, 2}), 0.0);
    EXPECT_EQ(one.majorant({20, 5, 7}), 0.0);
    EXPECT_EQ(one.minorant({20, 5, 2}), 0.0);
    EXPECT_TRUE(walk(one, Ray({-5, 20, 2}, {1, 0, 0}), 0, 100).empty());
    const std::vector<Segment> across = walk(one, Ray({20, -5, 2}, {0, 1, 0}), 0, 100);
    ASSERT_EQ(across.size(), 1u);
    EXPECT_NEAR(across[0].t0, 4, 1e-12);
    EXPECT_NEAR(across[0].t1, 15, 1e-12);
    expectBounds(box, one, 10000);
}

TEST(MajorantGrid, WalkCoversTheGridPartOfTheSegmentOnceInOrder) {
    // Support −1 … 41 voxels of 1: cells from −1, 6 × 8 = 48 voxels: grid [−1, 47].
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {39, 39, 39}, 1.0f));
    MajorantGrid grid(box);
    Random random(3);
    for (int i = 0; i < 2000; ++i) {
        const dvec3 o = dvec3(random.uniform(), random.uniform(), random.uniform()) * 60.0 - 6.0;
        const dvec3 d = glm::normalize(dvec3(random.uniform(), random.uniform(), random.uniform()) - 0.5);
        const double tmin = random.uniform() * 10, tmax = tmin + random.uniform() * 80;
        // The expected clipped interval, from slabs.
        double t0 = tmin, t1 = tmax;
        for (int a = 0; a < 3; ++a) {
            const double ta = (-1 - o[a]) / d[a], tb = (47 - o[a]) / d[a];
            t0 = std::max(t0, std::min(ta, tb)), t1 = std::min(t1, std::max(ta, tb));
        }
        const std::vector<Segment> segments = walk(grid, Ray(o, d), tmin, tmax);
        if (t0 < t1 - 1e-9) {
            ASSERT_FALSE(segments.empty());
            EXPECT_NEAR(segments.front().t0, t0, 1e-9);
            EXPECT_NEAR(segments.back().t1, t1, 1e-9);
            expectTiling(segments, segments.front().t0, segments.back().t1);
        } else if (!(t0 < t1)) {
            EXPECT_TRUE(segments.empty());
        }
    }
}

TEST(MajorantGrid, RaysMissingTheGridGiveNoSegment) {
    MajorantGrid grid(densityOf(boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f)));
    EXPECT_TRUE(walk(grid, Ray({-5, 20, 0}, {1, 0, 0}), 0, 100).empty());
    EXPECT_TRUE(walk(grid, Ray({-5, -5, -5}, {-1, -1, -1}), 0, 100).empty());  // pointing away
    EXPECT_TRUE(walk(grid, Ray({-5, 3, 3}, {1, 0, 0}), 0, 2).empty());        // stops short
    EXPECT_TRUE(walk(grid, Ray({3, 3, 3}, {0, 0, 0}), 0, 0).empty());         // empty interval
}

TEST(MajorantGrid, RaysAlongAxesThroughCornersAndWithZeroComponents) {
    // Two boxes with clear air between: cells of majorant 0 are reported between them.
    auto twoBoxes = boxGrid({0, 0, 0}, {7, 7, 7}, 1.0f);
    twoBoxes->tree().fill(openvdb::CoordBBox({40, 0, 0}, {47, 7, 7}), 3.0f, true);
    DensityGrid density = densityOf(twoBoxes);
    MajorantGrid grid(density);  // grid [−1, 55] × [−1, 15] × [−1, 15]
    std::vector<Segment> x = walk(grid, Ray({-10, 3, 3}, {1, 0, 0}), 0, 100);
    expectTiling(x, 9, 65);
    const auto steps = majorantSteps(x);
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_EQ(steps[0].second, 1.0);
    EXPECT_EQ(steps[1].second, 0.0);
    EXPECT_EQ(steps[2].second, 3.0);
    EXPECT_DOUBLE_EQ(steps[1].first, 9 + 16.0);  // cells 0, 1 (from −1 to 15) touch the first box's support (−1 … 8)
    // Backwards along x, on a cell face (y = 7 is the face between cells 0 and 1).
    expectTiling(walk(grid, Ray({60, 7, 3}, {-1, 0, 0}), 0, 100), 5, 61);
    // Along the grid's outer face, and along an edge.
    expectTiling(walk(grid, Ray({-10, 15, 3}, {1, 0, 0}), 0, 100), 9, 65);
    expectTiling(walk(grid, Ray({-10, -1, -1}, {1, 0, 0}), 0, 100), 9, 65);
    // Diagonals through cell corners, in all sign combinations.
    for (int signs = 0; signs < 8; ++signs) {
        const dvec3 d(signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? -1 : 1);
        const dvec3 o = dvec3(7) - 8.0 * d;  // corner (7,7,7), one cell back
        expectTiling(walk(grid, Ray(o, d), 0, 16), 0, 16);
    }
    // Zero components: in a plane, and not moving at all.
    expectTiling(walk(grid, Ray({-10, -10, 3}, {1, 1, 0}), 0, 100), 9, 25);
    std::vector<Segment> still = walk(grid, Ray({3, 3, 3}, {0, 0, 0}), 0, 5);
    ASSERT_EQ(still.size(), 1u);
    EXPECT_EQ(still[0].majorant, 1.0);
    expectBounds(density, grid, 100000);
}

TEST(MajorantGrid, CallbackStopsTheWalk) {
    auto twoBoxes = boxGrid({0, 0, 0}, {7, 7, 7}, 1.0f);
    twoBoxes->tree().fill(openvdb::CoordBBox({40, 0, 0}, {47, 7, 7}), 3.0f, true);
    MajorantGrid grid(densityOf(twoBoxes));
    int calls = 0;
    grid.forEachBound(Ray({-10, 3, 3}, {1, 0, 0}), 0, 100, [&](double, double, double, double) { return ++calls < 2; });
    EXPECT_EQ(calls, 2);
}

TEST(MajorantGrid, RotatedGridIsBoundedToo) {
    auto grid = boxGrid({0, 0, 0}, {20, 9, 5}, 1.0f);
    grid->tree().setValue({3, 3, 3}, 4.0f);
    openvdb::math::Transform::Ptr t = openvdb::math::Transform::createLinearTransform(0.3);
    t->postRotate(0.7, openvdb::math::Z_AXIS);
    t->postRotate(-0.4, openvdb::math::X_AXIS);
    t->postTranslate(openvdb::Vec3d(1, -2, 0.5));
    grid->setTransform(t);
    DensityGrid density = densityOf(grid);
    expectBounds(density, MajorantGrid(density), 100000);
}

TEST(MajorantGrid, HugeSparseGridKeepsAFewHundredThousandCells) {
    auto grid = boxGrid({0, 0, 0}, {0, 0, 0}, 1.0f);
    grid->tree().setValue({5000, 3000, 4000}, 2.0f);
    MajorantGrid majorant(densityOf(grid));
    const glm::ivec3 n = majorant.resolution();
    EXPECT_LE(double(n.x) * n.y * n.z, MajorantGrid::kMaxCells);
    EXPECT_GT(majorant.voxelsPerCell(), 8);
    EXPECT_EQ(majorant.majorant({0, 0, 0}), 1.0);
    EXPECT_EQ(majorant.majorant({5000, 3000, 4000}), 2.0);
}

TEST(MajorantGrid, EmptyGridHasNoSegment) {
    openvdb::initialize();
    MajorantGrid grid(densityOf(openvdb::FloatGrid::create(0.0f)));
    EXPECT_TRUE(walk(grid, Ray({0, 0, 0}, {0, 0, 0}), -1, 1).empty());
    EXPECT_EQ(grid.majorant({0, 0, 0}), 0.0);
}

TEST(MajorantGrid, RealGridsAreBoundedEverywhere) {
    for (const char* name : {"openvdb_smoke1.vdb", "wdas_cloud_sixteenth.vdb", "houdini_unit_box_density1.vdb",
                             "fds_room_fire_mesh2_soot/soot_t180.vdb"}) {
        BRUME_SHARED_GRID_OR_SKIP(path, name);
        setWarningsEnabled(false);
        DensityGrid density(path);
        setWarningsEnabled(true);
        const auto start = std::chrono::steady_clock::now();
        MajorantGrid grid(density);
        const glm::ivec3 n = grid.resolution();
        std::printf("%s: %d × %d × %d cells of %d³ voxels, built in %.3f s\n", name, n.x, n.y, n.z,
                    grid.voxelsPerCell(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        SCOPED_TRACE(name);
        expectBounds(density, grid, 100000);
    }
}

}  // namespace
}  // namespace brume
