#include "geometry/local_frame.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace brume;

namespace {

Bounds3 box(const dvec3& centre, double half) { return {centre - half, centre + half}; }

}  // namespace

// The origin is a median of the items' centres, so moving every item moves it as much (to the rounding of
// the moved coordinates), and the typical size is the median item's: the frame of a model does not depend
// on where it stands, and one huge or far item moves neither.
TEST(LocalFrame, FollowsTheModelNotItsOutliers) {
    std::vector<Bounds3> model;
    for (int i = 0; i < 9; ++i) model.push_back(box(dvec3(i % 3, i / 3, 0.5 * i), 0.25 + 0.05 * i));
    LocalFrame here(model);
    const dvec3 utm(512345.6, 5412345.7, 120);
    std::vector<Bounds3> moved;
    for (const Bounds3& b : model) moved.push_back({b.lo + utm, b.hi + utm});
    LocalFrame there(moved);
    EXPECT_NEAR(glm::length(there.origin() - utm - here.origin()), 0, 1e-9);
    EXPECT_NEAR(there.typicalSize(), here.typicalSize(), 1e-9 * here.typicalSize());
    std::vector<Bounds3> outliers = model;
    outliers.push_back(box(dvec3(0, 0, -1), 1e6));  // a ground 2000 km wide
    outliers.push_back(box(dvec3(1e12, 0, 0), 0.01));  // a ball far away
    LocalFrame withOutliers(outliers);
    EXPECT_LE(glm::length(withOutliers.origin() - here.origin()), 2.0);
    EXPECT_TRUE(withOutliers.huge(outliers[9]));
    EXPECT_FALSE(withOutliers.near(outliers[9]));
    EXPECT_TRUE(withOutliers.reaches(outliers[9]));
    EXPECT_FALSE(withOutliers.near(outliers[10]));
    EXPECT_FALSE(withOutliers.reaches(outliers[10]));
    for (int i = 0; i < 9; ++i) EXPECT_TRUE(!withOutliers.huge(outliers[i]) && withOutliers.near(outliers[i]));
}

// A prototype's items are huge beside the world it is placed in too.
TEST(LocalFrame, PrototypesAreHugeBesideTheirWorld) {
    std::vector<Bounds3> ground{box(dvec3(0), 1e6), box(dvec3(1e6), 1e6)};
    EXPECT_FALSE(LocalFrame(ground).huge(ground[0]));
    EXPECT_TRUE(LocalFrame(ground, 0.5).huge(ground[0]));
}
