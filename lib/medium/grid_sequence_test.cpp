#include "medium/grid_sequence.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "medium/testing.h"
#include "sampling/random.h"
#include "util/error.h"

namespace brume {
namespace {

using namespace medium::testing;

TEST(GridSequence, DensityIsLinearInTimeBetweenKeyFramesAndClampedOutside) {
    // A box of 1 at t = 10 s that has grown and thickened to 3 at t = 20 s.
    GridSequence smoke({{20, densityOf(boxGrid({0, 0, 0}, {19, 19, 19}, 3.0f))},
                        {10, densityOf(boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f))}});
    EXPECT_EQ(smoke.keyFrames().front().time, 10);  // sorted
    EXPECT_DOUBLE_EQ(smoke.density({5, 5, 5}, 10), 1.0);
    EXPECT_DOUBLE_EQ(smoke.density({5, 5, 5}, 12.5), 1.5);
    EXPECT_DOUBLE_EQ(smoke.density({5, 5, 5}, 20), 3.0);
    EXPECT_DOUBLE_EQ(smoke.density({15, 5, 5}, 15), 1.5);  // only in the later frame
    EXPECT_DOUBLE_EQ(smoke.density({5, 5, 5}, -100), 1.0);
    EXPECT_DOUBLE_EQ(smoke.density({15, 5, 5}, 1e6), 3.0);
    EXPECT_NEAR(smoke.bounds().hi.x, 20, 1e-12);
    MajorantGrid during = smoke.majorant(12, 18);
    EXPECT_EQ(during.majorant({5, 5, 5}), 3.0);
    EXPECT_EQ(during.majorant({15, 5, 5}), 3.0);
    MajorantGrid before = smoke.majorant(0, 10);  // the first frame alone
    EXPECT_EQ(before.majorant({5, 5, 5}), 1.0);
    EXPECT_EQ(before.majorant({30, 5, 5}), 0.0);
}

TEST(GridSequence, NoFrameOrTwoAtOneTimeAreRefused) {
    EXPECT_THROW(GridSequence(std::vector<KeyFrame>{}), Error);
    DensityGrid box = densityOf(boxGrid({0, 0, 0}, {1, 1, 1}, 1.0f));
    EXPECT_THROW(GridSequence({{30, box}, {30, box}}), Error);
}

TEST(GridSequence, FdsSootFramesInterpolateBetweenTheirValuesAndMajorantBoundsThem) {
    std::vector<KeyFrame> frames;
    for (int t = 30; t <= 180; t += 30) {
        char name[64];
        std::snprintf(name, sizeof name, "fds_room_fire_mesh2_soot/soot_t%03d.vdb", t);
        BRUME_SHARED_GRID_OR_SKIP(path, name);
        frames.push_back({double(t), DensityGrid(path)});
    }
    GridSequence soot(frames);
    Random random(11);
    const Bounds3 b = soot.bounds();
    int between = 0;
    for (int i = 0; i < 20000; ++i) {
        const dvec3 p = b.lo + dvec3(random.uniform(), random.uniform(), random.uniform()) * (b.hi - b.lo);
        const int k = int(random.uniform() * 5);
        const double a = frames[k].grid.density(p), c = frames[k + 1].grid.density(p);
        EXPECT_EQ(soot.density(p, frames[k].time), a);
        EXPECT_EQ(soot.density(p, frames[k + 1].time), c);
        const double t = frames[k].time + random.uniform() * 30, d = soot.density(p, t);
        EXPECT_GE(d, std::min(a, c) * (1 - 1e-12));
        EXPECT_LE(d, std::max(a, c) * (1 + 1e-12));
        between += a != c;
    }
    EXPECT_GT(between, 1000);  // the smoke does change
    // The majorant over 45 … 100 s (frames 30 … 120 s) bounds every instant in it.
    MajorantGrid majorant = soot.majorant(45, 100);
    for (int i = 0; i < 20000; ++i) {
        const dvec3 p = b.lo + dvec3(random.uniform(), random.uniform(), random.uniform()) * (b.hi - b.lo);
        const double t = 45 + random.uniform() * 55;
        ASSERT_GE(majorant.majorant(p), soot.density(p, t));
    }
}

}  // namespace
}  // namespace brume
