#include "geometry/transform.h"

#include <gtest/gtest.h>

#include <vector>

using namespace brume;

namespace {

ParsedTransform parse(std::vector<std::string> args) { return parseTransform(args); }

void expectNear(const dvec3& a, const dvec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

}  // namespace

// Radiance's rotations are right-handed about each axis: -rz 90 takes x to y, -rx 90 takes y to z.
TEST(Transform, RotationsAreRightHanded) {
    expectNear(parse({"-rz", "90"}).transform.point({1, 0, 0}), {0, 1, 0});
    expectNear(parse({"-rx", "90"}).transform.point({0, 1, 0}), {0, 0, 1});
    expectNear(parse({"-ry", "90"}).transform.point({0, 0, 1}), {1, 0, 0});
}

// Transforms apply in the order written: rotate then translate differs from translate then rotate.
TEST(Transform, AppliesInOrderWritten) {
    expectNear(parse({"-rz", "90", "-t", "1", "0", "0"}).transform.point({1, 0, 0}), {1, 1, 0});
    expectNear(parse({"-t", "1", "0", "0", "-rz", "90"}).transform.point({1, 0, 0}), {0, 2, 0});
}

TEST(Transform, ScaleAndMirrorsMultiplyTheSignedScale) {
    auto p = parse({"-s", "2", "-mx", "-my", "-mz"});
    EXPECT_EQ(p.used, 5u);
    EXPECT_DOUBLE_EQ(p.transform.scale, -2);
    EXPECT_TRUE(p.transform.mirrors());
    expectNear(p.transform.point({1, 2, 3}), {-2, -4, -6});
    expectNear(p.transform.vector({0, 0, 1}), {0, 0, -2});
}

// `-i n` repeats the transforms that follow it (up to the next -i) n times.
TEST(Transform, IterationRepeatsTheFollowingGroup) {
    auto p = parse({"-t", "0", "0", "1", "-i", "3", "-t", "1", "0", "0", "-i", "2", "-s", "2"});
    EXPECT_EQ(p.used, 14u);
    expectNear(p.transform.point({0, 0, 0}), {12, 0, 4});
    EXPECT_DOUBLE_EQ(p.transform.scale, 4);
}

// Parsing stops where the transform ends, as Radiance's xf(): the caller decides whether leftovers are an error.
TEST(Transform, StopsAtTheFirstArgumentNotPartOfATransform) {
    EXPECT_EQ(parse({"-t", "1", "2", "3", "chair.rad"}).used, 4u);
    EXPECT_EQ(parse({"-t", "1", "2"}).used, 0u);
    EXPECT_EQ(parse({"-s", "0"}).used, 0u);
    EXPECT_EQ(parse({"-rx", "ten"}).used, 0u);
    EXPECT_EQ(parse({"-rw", "10"}).used, 0u);
    EXPECT_EQ(parse({"-mx", "-n", "a"}).used, 1u);
}

TEST(Transform, InverseUndoesIt) {
    Transform t = parse({"-rx", "30", "-t", "1", "2", "3", "-s", "5", "-my", "-rz", "-70"}).transform;
    dvec3 p(0.3, -7, 11);
    expectNear(t.inverse().point(t.point(p)), p);
    EXPECT_DOUBLE_EQ(t.inverse().scale * t.scale, 1);
}
