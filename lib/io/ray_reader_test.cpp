#include "io/ray_reader.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace brume;

// Directions of any finite length are made unit without overflow or underflow; only 0 0 0 asks for a flush.
TEST(InputRay, DirectionsOfAnyFiniteLengthAreMadeUnit) {
    InputRay huge = inputRay({0, 0, 1, 1e300, 0, -1e300});
    EXPECT_FALSE(huge.zero);
    EXPECT_DOUBLE_EQ(huge.dir.x, std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(huge.dir.z, -std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(huge.maxDistance, 1e300 * std::sqrt(2.0));
    InputRay tiny = inputRay({0, 0, 1, 4.9e-324, 0, 0});
    EXPECT_FALSE(tiny.zero);
    EXPECT_EQ(tiny.dir, dvec3(1, 0, 0));
    EXPECT_GT(tiny.maxDistance, 0);
    EXPECT_TRUE(inputRay({1, 2, 3, 0, -0.0, 0}).zero);
}
