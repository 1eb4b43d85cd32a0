#include "medium/data_coverage.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace brume {
namespace {

// The shared FDS case's plan in little: two meshes side by side, x 0-5 and 5-10 (y, z 0-3), the second with data.
DataCoverage twoMeshes(const std::string& data) {
    return DataCoverage::parse("0 0 0 5 3 3; 5 0 0 10 3 3", data, "mesh 2: 3D smoke");
}

TEST(DataCoverage, MeasuresTheLengthOfALineInTheDomainWithoutData) {
    DataCoverage c = twoMeshes("5 0 0 10 3 3");
    EXPECT_TRUE(c.incomplete());
    EXPECT_EQ(c.note(), "mesh 2: 3D smoke");
    Ray along(dvec3(-1, 1, 1), dvec3(1, 0, 0));
    EXPECT_NEAR(c.uncoveredLength(along, 0, 20), 5, 1e-12);     // x 0-5 unknown, 5-10 known, the rest outside
    EXPECT_NEAR(c.uncoveredLength(along, 3, 8), 3, 1e-12);      // x 2-5 of x 2-7
    EXPECT_NEAR(c.uncoveredLength(along, 7, 20), 0, 1e-12);     // x 6-19: data, then outside the domain
    Ray across(dvec3(2.5, -1, 1), dvec3(0, 1, 0));              // through mesh 1 only
    EXPECT_NEAR(c.uncoveredLength(across, 0, 10), 3, 1e-12);
    Ray diagonal(dvec3(0, 0, 0), glm::normalize(dvec3(10, 3, 3)));
    EXPECT_NEAR(c.uncoveredLength(diagonal, 0, 100), 0.5 * glm::length(dvec3(10, 3, 3)), 1e-9);
}

TEST(DataCoverage, AFullDomainOrNoneLeavesNothingUnknown) {
    DataCoverage full = twoMeshes("0 0 0 10 3 3");
    EXPECT_FALSE(full.incomplete());
    EXPECT_EQ(full.uncoveredLength(Ray(dvec3(-1, 1, 1), dvec3(1, 0, 0)), 0, 20), 0);
    EXPECT_FALSE(twoMeshes("0 0 0 5 3 3; 5 0 0 10 3 3").incomplete());  // data in two pieces
    EXPECT_TRUE(twoMeshes("0 0 0 5 3 3; 5 0 1.8 10 3 2.3").incomplete());  // a layer of slice data
    DataCoverage none;
    EXPECT_FALSE(none.incomplete());
    EXPECT_EQ(none.uncoveredLength(Ray(dvec3(-1, 1, 1), dvec3(1, 0, 0)), 0, 20), 0);
}

TEST(DataCoverage, ALayerOfDataLeavesTheRestOfTheMeshUnknown) {
    DataCoverage c = twoMeshes("5 0 0 10 3 3; 0 0 1.8 5 3 2.3");
    Ray up(dvec3(2, 2, -1), dvec3(0, 0, 1));
    EXPECT_NEAR(c.uncoveredLength(up, 0, 10), 2.5, 1e-12);  // z 0-1.8 and 2.3-3
    Ray level(dvec3(-1, 1, 2), dvec3(1, 0, 0));
    EXPECT_NEAR(c.uncoveredLength(level, 0, 20), 0, 1e-12);  // in the layer, then in mesh 2
}

TEST(DataCoverage, FormatsWhatItParses) {
    std::vector<Bounds3> boxes = {{dvec3(0, 0, 0), dvec3(5, 3, 3)}, {dvec3(5, 0, 1.8), dvec3(10, 3, 2.3)}};
    DataCoverage c = DataCoverage::parse(DataCoverage::format(boxes), "");
    ASSERT_EQ(c.domain().size(), 2u);
    EXPECT_EQ(c.domain()[1].lo.z, 1.8);
    EXPECT_EQ(c.domain()[1].hi.x, 10);
    EXPECT_TRUE(c.incomplete());
}

TEST(DataCoverage, RefusesMalformedBoxes) {
    EXPECT_THROW(DataCoverage::parse("0 0 0 5 3", ""), Error);
    EXPECT_THROW(DataCoverage::parse("0 0 0 5 3 3 7", ""), Error);
    EXPECT_THROW(DataCoverage::parse("0 0 0 5 3 x", ""), Error);
    EXPECT_THROW(DataCoverage::parse("5 0 0 0 3 3", ""), Error);  // inverted
    EXPECT_THROW(DataCoverage::parse("0 0 0 5 3 3", "0 0 0 inf 1 1"), Error);
    try {
        DataCoverage::parse("", "1 2 3");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("brume:data"), std::string::npos);
    }
}

}  // namespace
}  // namespace brume
