#include "geometry/transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace brume {
namespace {

Transform parsed(const std::vector<std::string>& words) {
    ParsedTransform p = parseTransform(words);
    EXPECT_EQ(p.used, words.size());
    return p.transform;
}

TEST(Transform, RotationsTurnCounterClockwiseLookingDownTheAxis) {
    Transform rz = parsed({"-rz", "90"}), rx = parsed({"-rx", "90"}), ry = parsed({"-ry", "90"});
    // Exactly Radiance's numbers: the entries are cos and sin themselves, so x goes to (cos 90°, 1, 0).
    EXPECT_EQ(rz.point({1, 0, 0}), dvec3(std::cos(M_PI / 2), 1, 0));
    EXPECT_NEAR(rx.point({0, 1, 0}).z, 1, 1e-15);
    EXPECT_NEAR(ry.point({0, 0, 1}).x, 1, 1e-15);
}

TEST(Transform, OptionsApplyInTheOrderGiven) {
    EXPECT_EQ(parsed({"-t", "1", "0", "0", "-s", "2"}).point({0, 0, 0}), dvec3(2, 0, 0));
    EXPECT_EQ(parsed({"-s", "2", "-t", "1", "0", "0"}).point({0, 0, 0}), dvec3(1, 0, 0));
}

TEST(Transform, IterationRepeatsTheGroupBeforeTheNextIteration) {
    Transform t = parsed({"-i", "3", "-t", "1", "0", "0", "-i", "2", "-s", "-2"});
    EXPECT_EQ(t.point({0, 0, 0}), dvec3(12, 0, 0));
    EXPECT_EQ(t.scale, 4);
    EXPECT_FALSE(t.mirrors());
}

TEST(Transform, MirrorsAreOddNegativeScales) {
    EXPECT_TRUE(parsed({"-my"}).mirrors());
    EXPECT_FALSE(parsed({"-my", "-mz"}).mirrors());
    EXPECT_TRUE(parsed({"-s", "-1"}).mirrors());
    EXPECT_EQ(parsed({"-my"}).vector({1, 2, 3}), dvec3(1, -2, 3));
}

TEST(Transform, ParsingStopsAtWhatIsNotATransform) {
    std::vector<std::string> words{"-t", "1", "2", "x.rad"};
    EXPECT_EQ(parseTransform(words).used, 0u);
    std::vector<std::string> zero{"-rz", "10", "-s", "0"};
    EXPECT_EQ(parseTransform(zero).used, 2u);
}

}  // namespace
}  // namespace brume
