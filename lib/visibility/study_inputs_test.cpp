#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"
#include "visibility/observers.h"
#include "visibility/sign_list.h"

namespace brume {
namespace {

template <typename Read>
std::string errorOf(Read read) {
    try {
        read();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// The error `read(in, name)` gives for the text `text` named `name`.
template <typename Reader>
std::string errorReading(Reader read, const std::string& text, const std::string& name) {
    return errorOf([&] {
        std::istringstream in(text);
        read(in, name);
    });
}

TEST(SignList, ReadsKindsAndJinsConstants) {
    std::istringstream in("# signs\nexit_a emitting\n\nplan reflecting 2.5  # a floor plan\nexit_b emitting 6\n");
    std::vector<SignEntry> signs = readSignList(in, "signs.txt");
    ASSERT_EQ(signs.size(), 3u);
    EXPECT_EQ(signs[0].name, "exit_a");
    EXPECT_EQ(signs[0].jinConstant, 8);
    EXPECT_EQ(signs[1].kind, SignKind::Reflecting);
    EXPECT_EQ(signs[1].jinConstant, 2.5);
    EXPECT_EQ(signs[1].where, "signs.txt:4");
    EXPECT_EQ(signs[2].jinConstant, 6);
    auto bad = [](const std::string& text) { return errorReading(readSignList, text, "s"); };
    EXPECT_EQ(bad("a glowing\n"), "s:1: sign 'a': kind 'glowing' is neither emitting nor reflecting");
    EXPECT_EQ(bad("\na emitting x\n"), "s:2: sign 'a': Jin's C 'x' is not a number");
    EXPECT_EQ(bad("a emitting -1\n"), "s:1: sign 'a': Jin's C must be > 0");
    EXPECT_EQ(bad("a emitting nan\n"), "s:1: sign 'a': Jin's C 'nan' is not a number");
    EXPECT_EQ(bad("a\n"), "s:1: expected 'polygon emitting|reflecting [C]'");
    EXPECT_EQ(bad("a emitting\na reflecting\n"), "s:2: sign 'a' is listed twice (s:1)");
    EXPECT_EQ(bad("# none\n"), "s: no signs");
}

TEST(Observers, GridCellsAndWaypoints) {
    std::vector<Observer> grid = gridObservers(makeGrid(10, 2, 15, 4, 0.5), 1.6);
    ASSERT_EQ(grid.size(), 40u);
    EXPECT_EQ(grid[0].eye, glm::dvec3(10.25, 3.75, 1.6));  // row 0 at the largest y, as a picture's top
    EXPECT_EQ(grid[0].column, 0);
    EXPECT_EQ(grid[0].name, "cell_0_0");
    EXPECT_EQ(grid[39].eye, glm::dvec3(14.75, 2.25, 1.6));
    EXPECT_EQ(grid[39].row, 3);
    EXPECT_EQ(errorOf([] { makeGrid(0, 0, 1, 1, 0); }), "the grid's step must be > 0");
    EXPECT_EQ(errorOf([] { makeGrid(0, 0, 0, 1, 0.1); }), "the grid's rectangle is empty: x1 > x0 and y1 > y0 are needed");
    EXPECT_EQ(errorOf([] { makeGrid(0, 0, 1e4, 1e4, 1); }), "the grid has more than 4 million points: take a larger step");
    std::istringstream in("door 10.3 3 1.6\n# the middle\nmid 12 3 1.6 # by the luminaire\n");
    std::vector<Observer> w = readWaypoints(in, "route.txt");
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[1].name, "mid");
    EXPECT_EQ(w[1].eye, glm::dvec3(12, 3, 1.6));
    auto bad = [](const std::string& text) { return errorReading(readWaypoints, text, "r"); };
    EXPECT_EQ(bad("a 1 2\n"), "r:1: expected 'name x y z', found 3 words");
    EXPECT_EQ(bad("a 1 2 z\n"), "r:1: z 'z' is not a number");
    EXPECT_EQ(bad("a 1 2 3\na 1 2 3\n"), "r:2: waypoint 'a' is named twice");
    EXPECT_EQ(bad("a,b 1 2 3\n"), "r:1: waypoint 'a,b': a name without commas or quotes, for the CSV");
    EXPECT_EQ(bad(""), "r: no waypoints");
}

}  // namespace
}  // namespace brume
