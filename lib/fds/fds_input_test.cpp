#include "fds/fds_input.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace brume {
namespace {

std::vector<FdsGroup> read(const std::string& text) {
    std::istringstream in(text);
    return readFdsInput(in, "case.fds");
}

std::string error(const std::string& text) {
    try {
        read(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(FdsInput, ReadsGroupsAsFdsDoes) {
    auto groups = read("&HEAD CHID='model' TITLE='a / b' /\n"
                       "// a comment with & and / in it\n"
                       "Free text: &NOT a group, mid-line.\n"
                       "&OBST ID=\"wall\" SURF_ID='concrete'\n"
                       "      XB=9.9,10.0, 0,10, 0,3.0D0 /  trailing text\n"
                       "  &SLCF QUANTITY='TEMPERATURE',  CELL_CENTERED=T, PBZ=2.000 /\n"
                       "&DUMP PLOT3D_QUANTITY(1:2)='TEMPERATURE','U-VELOCITY' /\n");
    ASSERT_EQ(groups.size(), 4u);
    EXPECT_EQ(groups[0].name, "HEAD");
    EXPECT_EQ(groups[0].text("TITLE"), "a / b");
    EXPECT_EQ(groups[1].name, "OBST");
    EXPECT_EQ(groups[1].where, "case.fds:4");
    EXPECT_EQ(groups[1].text("ID"), "wall");
    EXPECT_EQ(*groups[1].numbers("XB", 6), (std::vector<double>{9.9, 10, 0, 10, 0, 3}));
    EXPECT_EQ(groups[2].text("CELL_CENTERED"), "T");
    EXPECT_EQ(*groups[2].numbers("PBZ", 1), std::vector<double>{2});
    EXPECT_EQ(groups[3].find("PLOT3D_QUANTITY(1:2)")->size(), 2u);
    EXPECT_FALSE(groups[1].text("COLOR"));
}

TEST(FdsInput, NamesWhatIsWrongAndWhere) {
    EXPECT_EQ(error("&OBST XB=0,1,0,1,0,1\n"), "case.fds:1: &OBST is not closed by '/'");
    EXPECT_EQ(error("\n&SURF ID='open /\n"), "case.fds:2: a string not closed by '");
    EXPECT_EQ(error("&MESH IJK= /\n"), "case.fds:1: &MESH IJK has no value");
    EXPECT_EQ(error("&MESH 12 /\n"), "case.fds:1: &MESH: expected a parameter (NAME=value), not '12 /\n'");
    auto groups = read("&OBST XB=0,1,0,x,0,1 /\n&OBST XB=0,1 /\n");
    EXPECT_THROW(groups[0].numbers("XB", 6), Error);
    try {
        groups[1].numbers("XB", 6);
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "case.fds:2: &OBST XB: expected 6 numbers, found 2");
    }
}

}  // namespace
}  // namespace brume
