#include "fds/case_geometry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "fds/testing.h"
#include "util/error.h"

namespace brume {
namespace {

CaseGeometry geometryOf(const std::string& text) {
    std::istringstream in(text);
    return caseGeometry(readFdsInput(in, "case.fds"));
}

dvec3 normalOf(const std::array<dvec3, 4>& c) { return glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0])); }

// Two meshes of different heights side by side: the domain's walls are their faces less the one they share,
// the taller one's step over the lower included; a wall with a door (a HOLE) is three boxes; an OPEN vent leaves
// its rectangle out of the wall it is on; a burner faces up.
TEST(CaseGeometry, WallsOfTheDomainSolidsLessHolesAndOpenings) {
    CaseGeometry g = geometryOf("&MESH XB=0,5,0,4,0,3 /\n&MESH XB=5,10,0,4,0,4 /\n"
                                "&SURF ID='wall' RGB=255,255,255 /\n&SURF ID='fire' COLOR='RED' /\n"
                                "&OBST ID='w' SURF_ID='wall' XB=4.9,5.0,0,4,0,3 /\n"
                                "&HOLE XB=4.8,5.1,1,2,0,2.2 /\n"
                                "&VENT SURF_ID='OPEN' XB=10,10,1,2,0,2 /\n"
                                "&VENT SURF_ID='fire' XB=7,8,1,2,0,0 /\n");
    ASSERT_EQ(g.meshes.size(), 2u);
    EXPECT_EQ(g.solids.size(), 3u);  // beside the door on each side, and over it
    EXPECT_TRUE(g.inSolid({4.95, 0.5, 1}));
    EXPECT_FALSE(g.inSolid({4.95, 1.5, 1}));   // in the door
    EXPECT_TRUE(g.inSolid({4.95, 1.5, 2.5}));  // over it
    double area = 0;
    for (const CaseRectangle& w : g.walls) {
        const std::array<dvec3, 4> c = w.corners();
        const dvec3 centre = 0.25 * (c[0] + c[1] + c[2] + c[3]), n = normalOf(c);
        EXPECT_TRUE(g.inside(centre + 0.01 * n)) << "a wall faces out of the domain";
        area += (w.hi[0] - w.lo[0]) * (w.hi[1] - w.lo[1]);
    }
    // The boxes' faces: floors and roofs 4 x 20, sides 2 x (5 x 3 + 5 x 4), ends 4 x 3 + 4 x 4; of the shared
    // plane only the taller mesh's step, 4 x 1, stays; the open vent, 1 x 2, is out.
    EXPECT_NEAR(area, 80 + 70 + 12 + 16 + 4 - 2, 1e-9);
    ASSERT_EQ(g.openings.size(), 1u);
    ASSERT_EQ(g.vents.size(), 1u);
    EXPECT_EQ(g.vents[0].facing, 1);
    EXPECT_NEAR(normalOf(g.vents[0].corners()).z, 1, 1e-12);
    EXPECT_EQ(g.surfaces.at("fire").rgb, (std::array<double, 3>{1, 0, 0}));
    EXPECT_TRUE(g.surfaces.at("wall").coloured);
    EXPECT_TRUE(g.warnings.empty());
}

TEST(CaseGeometry, WarnsOfWhatItCannotPlace) {
    CaseGeometry g = geometryOf("&MESH XB=0,5,0,4,0,3 /\n&SURF ID='s' COLOR='NO SUCH COLOUR' /\n"
                                "&OBST XB=1,2,1,2,0,1 SURF_ID='nowhere' /\n&VENT SURF_ID='OPEN' XB=2,3,1,2,0,1 /\n"
                                "&VENT SURF_ID='OPEN' XB=2,3,1,2,1,1 /\n");
    ASSERT_EQ(g.warnings.size(), 4u);
    EXPECT_EQ(g.warnings[0], "case.fds:2: &SURF COLOR 'NO SUCH COLOUR' is not a colour name known here: grey .5");
    EXPECT_EQ(g.warnings[1], "case.fds:3: &OBST SURF_ID 'nowhere' is no &SURF of the case: grey .5");
    EXPECT_EQ(g.warnings[2], "case.fds:4: &VENT is not a plane rectangle (one XB pair equal): left out");
    EXPECT_EQ(g.warnings[3], "case.fds:5: &VENT OPEN on no wall of the domain: left out");
    EXPECT_THROW(geometryOf("&OBST XB=1,2,1,2,0,1 /\n"), Error);  // no mesh
    EXPECT_THROW(geometryOf("&MESH XB=5,0,0,4,0,3 /\n"), Error);  // inverted
}

// The shared FDS case: four walls cut by four doors make 12 boxes; the hall's north door is open.
TEST(CaseGeometry, TheSharedCasesBuilding) {
    const std::string dir = fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    std::ifstream in(dir + "/model.fds");
    CaseGeometry g = caseGeometry(readFdsInput(in, "model.fds"));
    EXPECT_EQ(g.meshes.size(), 8u);
    EXPECT_EQ(g.solids.size(), 12u);
    EXPECT_TRUE(g.warnings.empty());
    EXPECT_FALSE(g.inSolid({9.95, 3.87, 1}));  // the door between the rooms and the hall
    EXPECT_TRUE(g.inSolid({9.95, 3.87, 2.5}));
    ASSERT_EQ(g.openings.size(), 1u);
    for (const CaseRectangle& w : g.walls)
        EXPECT_FALSE(w.axis == 1 && w.at == 10 && w.lo[0] < 17.5 && w.hi[0] > 17.5 && w.lo[1] < 1 && w.hi[1] > 1);
}

}  // namespace
}  // namespace brume
