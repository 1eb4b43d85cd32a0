#include "medium/density_grid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "medium/testing.h"
#include "sampling/random.h"
#include "util/error.h"

namespace brume {
namespace {

using namespace medium::testing;

// ∫ density along the segment a→b (midpoint rule; exact enough for piecewise-linear profiles at this step).
double opticalDepth(const DensityGrid& grid, dvec3 a, dvec3 b, int steps = 20000) {
    double sum = 0;
    for (int i = 0; i < steps; ++i) sum += grid.density(a + (i + 0.5) / steps * (b - a));
    return sum * glm::length(b - a) / steps;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(DensityGrid, BoundsAreWhereInterpolationReaches) {
    // Voxels 0..9 of 0.1: centres 0 … 0.9, cells −0.05 … 0.95, interpolation −0.1 … 1.0.
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f, 0.1));
    EXPECT_NEAR(box.bounds().lo.x, -0.1, 1e-12);
    EXPECT_NEAR(box.bounds().lo.z, -0.1, 1e-12);
    EXPECT_NEAR(box.bounds().hi.y, 1.0, 1e-12);
    EXPECT_EQ(box.activeVoxelCount(), 1000u);
    EXPECT_EQ(box.maxDensity(), 1.0);
}

TEST(DensityGrid, ConstantBoxIsConstantBetweenItsOuterVoxelCentresAndFallsToZeroOneVoxelBeyond) {
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {9, 9, 9}, 2.0f, 0.1));
    EXPECT_DOUBLE_EQ(box.density({0.45, 0.45, 0.45}), 2.0);
    EXPECT_DOUBLE_EQ(box.density({0.0, 0.3, 0.9}), 2.0);     // outermost voxel centres
    EXPECT_NEAR(box.density({-0.05, 0.45, 0.45}), 1.0, 1e-9);  // cell face: half way down
    EXPECT_NEAR(box.density({0.45, 0.95, 0.45}), 1.0, 1e-9);
    EXPECT_NEAR(box.density({-0.05, -0.05, 0.45}), 0.5, 1e-9);  // cell edge
    EXPECT_NEAR(box.density({1.0, 0.45, 0.45}), 0.0, 1e-9);    // bounds
    EXPECT_EQ(box.density({1.2, 0.45, 0.45}), 0.0);
    EXPECT_EQ(box.density({-50, 7, 1e6}), 0.0);
}

TEST(DensityGrid, InterpolationKeepsTheBoxsOpticalDepthAtItsCellExtent) {
    // 10 voxels of 0.1 at density 1: τ = 1.0 across, the ramps beyond the outer centres making up the half cells.
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f, 0.1));
    EXPECT_NEAR(opticalDepth(box, {-0.5, 0.45, 0.45}, {1.5, 0.45, 0.45}), 1.0, 1e-6);
}

// 7 × 5 × 6 voxels of random densities in [0, 2) (drawn from `seed`), in a grid turned, stretched and moved far
// from the origin (an affine index-to-world map).
DensityGrid randomGrid(uint64_t seed) {
    openvdb::initialize();
    auto vdb = openvdb::FloatGrid::create(0.0f);
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preRotate(openvdb::math::Z_AXIS, 0.3);
    m.preRotate(openvdb::math::X_AXIS, 0.2);
    m.preScale(openvdb::Vec3d(0.1, 0.15, 0.12));
    m.postTranslate(openvdb::Vec3d(5e5, 5e6, 3));
    vdb->setTransform(openvdb::math::Transform::createLinearTransform(m));
    vdb->setGridClass(openvdb::GRID_FOG_VOLUME);
    Random random(seed, seed);
    auto acc = vdb->getAccessor();
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 6; ++k) acc.setValue(openvdb::Coord(i, j, k), float(random.uniform() * 2));
    return densityOf(vdb);
}

// The exact integral along a ray (DensityGrid::integral) against a fine midpoint rule (whose own error, for
// these cubic pieces at 1/20000 of the way, is far below 1e-6): random voxels in a grid turned, stretched and
// moved (an affine index-to-world map), rays through it in random directions, along an axis, in a plane of voxel
// centres, and starting and ending inside it; and an empty stretch.
TEST(DensityGrid, IntegralAlongARayIsExact) {
    const DensityGrid grid = randomGrid(3);
    Random random(3, 3);
    const Bounds3 b = grid.bounds();
    const dvec3 centre = 0.5 * (b.lo + b.hi);
    auto along = [&](const dvec3& a, const dvec3& e) {
        Ray ray{a, glm::normalize(e - a)};
        double length = glm::length(e - a);
        EXPECT_NEAR(grid.integral(ray, 0, length), opticalDepth(grid, a, e), 1e-6 * (1 + opticalDepth(grid, a, e)))
            << a.x << " " << a.y << " " << a.z;
    };
    for (int n = 0; n < 20; ++n) {
        dvec3 w(random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5);
        along(centre - 2.0 * w, centre + 2.0 * w);
        along(centre - 0.1 * w, centre + 0.3 * w);  // inside to inside
    }
    const glm::dmat4 world = grid.voxels().worldFromIndex();
    auto at = [&](double i, double j, double k) { return dvec3(world * glm::dvec4(i, j, k, 1)); };
    along(at(-2, 2, 3), at(9, 2, 3));      // along a row of voxel centres
    along(at(2.5, -2, 1.5), at(2.5, 8, 1.5));  // along an axis between them
    Ray away{centre + dvec3(10, 0, 0), dvec3(1, 0, 0)};
    EXPECT_EQ(grid.integral(away, 0, 5), 0);
}

// The profile of a ray (DensityGrid::profile: a cubic per cell) gives the density the grid interpolates at every
// point of the ray and its exact integral from the stretch's start (against integral()), through the same turned,
// stretched and moved grid of random voxels; two profiles blended (key frames in time) are the blend of theirs.
TEST(DensityGrid, ProfileGivesTheDensityAndItsIntegralAlongTheRay) {
    const DensityGrid grid = randomGrid(4), other = randomGrid(5);
    const Bounds3 b = grid.bounds();
    const dvec3 centre = 0.5 * (b.lo + b.hi);
    Random random(7, 7);
    for (int n = 0; n < 10; ++n) {
        dvec3 w(random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5);
        Ray ray{centre - 2.0 * w, glm::normalize(w)};
        const double t0 = 0.3 * glm::length(w), t1 = 3.5 * glm::length(w);
        DensityProfile p = grid.profile(ray, t0, t1), q = other.profile(ray, t0, t1);
        DensityProfile blend = DensityProfile::sum(p, 0.3, q, 0.7);
        EXPECT_NEAR(p.total(), grid.integral(ray, t0, t1), 1e-9 * (1 + p.total()));
        for (int i = 0; i <= 50; ++i) {
            double t = t0 + (t1 - t0) * i / 50;
            double d = grid.density(ray.at(t)), e = other.density(ray.at(t));
            EXPECT_NEAR(p.density(t), d, 1e-5 * (1 + d)) << n << " " << t;
            EXPECT_NEAR(p.integral(t), grid.integral(ray, t0, t), 1e-9 * (1 + p.total())) << n << " " << t;
            EXPECT_NEAR(blend.density(t), 0.3 * d + 0.7 * e, 1e-5 * (1 + d + e)) << n << " " << t;
            EXPECT_NEAR(blend.integral(t), 0.3 * p.integral(t) + 0.7 * q.integral(t), 1e-9 * (1 + blend.total()));
        }
    }
}

TEST(DensityGrid, FogSphereIsDenseInsideAndClearOutside) {
    openvdb::initialize();
    auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(1.0f, openvdb::Vec3f(0), 0.05f);
    openvdb::tools::sdfToFogVolume(*sphere);
    DensityGrid fog = densityOf(sphere);
    EXPECT_DOUBLE_EQ(fog.density({0, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(fog.density({0.5, -0.3, 0.2}), 1.0);
    EXPECT_EQ(fog.density({1.1, 0, 0}), 0.0);
    EXPECT_EQ(fog.density({0.8, 0.8, 0}), 0.0);
    for (int a = 0; a < 3; ++a) {
        EXPECT_LT(fog.bounds().lo[a], -1.0);
        EXPECT_GT(fog.bounds().lo[a], -1.0 - 0.1);
        EXPECT_GT(fog.bounds().hi[a], 1.0 - 0.05);  // the fog's edge is the surface, the last voxel within it
        EXPECT_LT(fog.bounds().hi[a], 1.0 + 0.1);
    }
}

TEST(DensityGrid, LevelSetIsRefused) {
    openvdb::initialize();
    auto sdf = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(1.0f, openvdb::Vec3f(0), 0.05f);
    EXPECT_EQ(errorOf([&] { densityOf(sdf, "s.vdb: grid \"sphere\""); }),
              "s.vdb: grid \"sphere\" is a level set, not a density");
}

TEST(DensityGrid, HostileVoxelsReadAsZero) {
    auto grid = boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f);
    grid->tree().setValue({2, 2, 2}, std::numeric_limits<float>::quiet_NaN());
    grid->tree().setValue({4, 4, 4}, -3.0f);
    grid->tree().setValue({6, 6, 6}, std::numeric_limits<float>::infinity());
    grid->tree().setValueOff({20, 20, 20}, 7.0f);  // inactive, yet non-zero
    setWarningsEnabled(false);
    DensityGrid clean = densityOf(grid);
    setWarningsEnabled(true);
    EXPECT_EQ(clean.density({2, 2, 2}), 0.0);
    EXPECT_EQ(clean.density({4, 4, 4}), 0.0);
    EXPECT_EQ(clean.density({6, 6, 6}), 0.0);
    EXPECT_EQ(clean.density({20, 20, 20}), 0.0);
    EXPECT_DOUBLE_EQ(clean.density({2.5, 2, 2}), 0.5);  // no NaN leaks into the neighbours' interpolation
    EXPECT_EQ(clean.maxDensity(), 1.0);
}

TEST(DensityGrid, NonZeroBackgroundReadsAsZeroWithAWarning) {
    auto grid = boxGrid({0, 0, 0}, {3, 3, 3}, 1.0f);
    openvdb::tools::changeBackground(grid->tree(), 1.0f);
    testing::internal::CaptureStderr();
    DensityGrid box = densityOf(grid, "box.vdb: grid \"density\"");
    EXPECT_NE(testing::internal::GetCapturedStderr().find("box.vdb: grid \"density\" has background 1"),
              std::string::npos);
    EXPECT_EQ(box.density({100, 0, 0}), 0.0);
    EXPECT_EQ(box.density({5, 1, 1}), 0.0);
    EXPECT_EQ(box.density({1, 1, 1}), 1.0);
}

TEST(DensityGrid, EmptyGridHasEmptyBoundsAndNoDensity) {
    openvdb::initialize();
    DensityGrid empty = densityOf(openvdb::FloatGrid::create(0.0f));
    EXPECT_TRUE(empty.bounds().empty());
    EXPECT_EQ(empty.density({0, 0, 0}), 0.0);
    EXPECT_EQ(empty.activeVoxelCount(), 0u);
    EXPECT_EQ(empty.maxDensity(), 0.0);
}

TEST(DensityGrid, FileErrorsNameTheFileAndItsGrids) {
    openvdb::initialize();
    const std::string path = ::testing::TempDir() + "brume_density_grid_test.vdb";
    auto velocity = openvdb::Vec3SGrid::create();
    velocity->setName("vel");
    auto soot = boxGrid({0, 0, 0}, {1, 1, 1}, 1.0f);
    soot->setName("soot");
    openvdb::io::File(path).write({velocity, soot});
    EXPECT_EQ(errorOf([&] { DensityGrid grid(path); }),
              path + ": no grid \"density\" (the file holds \"soot\", \"vel\")");
    EXPECT_EQ(errorOf([&] { DensityGrid grid(path, "vel"); }),
              path + ": grid \"vel\" holds vec3s values, not float densities");
    EXPECT_EQ(DensityGrid(path, "soot").activeVoxelCount(), 8u);
    EXPECT_NE(errorOf([&] { DensityGrid grid(path + ".absent"); }).find(path + ".absent: "), std::string::npos);
    std::filesystem::remove(path);
}

TEST(DensityGrid, Smoke1StatisticsAreTheFilesHalfFloatsIncluded) {
    BRUME_SHARED_GRID_OR_SKIP(path, "openvdb_smoke1.vdb");
    const auto start = std::chrono::steady_clock::now();
    DensityGrid smoke(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("smoke1: loaded in %.3f s, tree %.1f MB (file %.1f MB)\n", seconds, smoke.memoryBytes() / 1e6,
                std::filesystem::file_size(path) / 1e6);
    EXPECT_EQ(smoke.activeVoxelCount(), 1049275u);
    EXPECT_NEAR(smoke.maxDensity(), 5.7148, 5e-5);
    // Voxel centres (−33.571, −12.143, −25.952) … (18.810, 93.095, 26.905), one voxel (1/2.1) beyond.
    const double voxel = 1 / 2.1;
    EXPECT_NEAR(smoke.bounds().lo.x, -33.571 - voxel, 1e-3);
    EXPECT_NEAR(smoke.bounds().lo.y, -12.143 - voxel, 1e-3);
    EXPECT_NEAR(smoke.bounds().hi.z, 26.905 + voxel, 1e-3);
    // The tree and its box copied into one array (a third of the box holds smoke: twice the tree at most).
    EXPECT_LT(smoke.memoryBytes(), 8 * std::filesystem::file_size(path));
    const auto lookups = std::chrono::steady_clock::now();
    double sum = 0;
    for (int i = 0; i < 1000000; ++i) sum += smoke.density({-10 + 1e-5 * i, 40, 0});
    std::printf("smoke1: %.0f ns per density lookup (sum %g)\n",
                std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - lookups).count() / 1e6, sum);
}

TEST(DensityGrid, WdasCloudCountsItsTilesAndReadsDensityInThem) {
    BRUME_SHARED_GRID_OR_SKIP(path, "wdas_cloud_sixteenth.vdb");
    DensityGrid cloud(path);
    const openvdb::FloatTree& tree = vdbOf(cloud).tree();
    EXPECT_EQ(cloud.activeVoxelCount(), 415642u);
    EXPECT_EQ(tree.activeLeafVoxelCount(), 349082u);  // a loader walking only leaves misses 66,560 voxels
    // Bounds from the transform (the file's "voxelsize" metadata, 0.0, is stale): centres ± 10/3.
    EXPECT_NEAR(cloud.bounds().lo.x, -220.0 - 10.0 / 3, 1e-3);
    EXPECT_NEAR(cloud.bounds().hi.y, 213.333 + 10.0 / 3, 1e-3);
    int tiles = 0;
    for (auto it = tree.cbeginValueOn(); it; ++it) {
        if (!it.isTileValue()) continue;
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        const openvdb::Vec3d centre = vdbOf(cloud).indexToWorld(box.getCenter());
        EXPECT_NEAR(cloud.density({centre.x(), centre.y(), centre.z()}), *it, 1e-6);
        ++tiles;
    }
    EXPECT_EQ(tiles, 66560 / 512);
}

TEST(DensityGrid, HoudiniBoxWithBackgroundOneIsABoxOfDensityOne) {
    BRUME_SHARED_GRID_OR_SKIP(path, "houdini_unit_box_density1.vdb");
    setWarningsEnabled(false);
    DensityGrid box(path);
    setWarningsEnabled(true);
    EXPECT_EQ(box.activeVoxelCount(), 9261u);
    EXPECT_NEAR(box.bounds().lo.x, -0.55, 1e-9);
    EXPECT_NEAR(box.bounds().hi.z, 0.55, 1e-9);
    EXPECT_DOUBLE_EQ(box.density({0, 0, 0}), 1.0);
    EXPECT_EQ(box.density({0.6, 0, 0}), 0.0);
    EXPECT_EQ(box.density({5, 0, 0}), 0.0);
    // σ_t = 1 per unit density: τ through the centre is the cell extent, 21 × 0.05.
    EXPECT_NEAR(opticalDepth(box, {-1, 0, 0}, {1, 0, 0}), 1.05, 1e-6);
}

TEST(DensityGrid, SphereLevelSetFileIsRefused) {
    BRUME_SHARED_GRID_OR_SKIP(path, "openvdb_sphere_levelset.vdb");
    EXPECT_EQ(errorOf([&] { DensityGrid grid(path, "ls_sphere"); }),
              path + ": grid \"ls_sphere\" is a level set, not a density");
    EXPECT_EQ(errorOf([&] { DensityGrid grid(path); }), path + ": no grid \"density\" (the file holds \"ls_sphere\")");
}

}  // namespace
}  // namespace brume
