#include "visibility/sign_layout.h"

#include <gtest/gtest.h>

#include <sstream>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace brume {
namespace {

std::vector<SignPlacement> read(const std::string& text) {
    std::istringstream in(text);
    return readSignPlacements(in, "signs.txt");
}

// A polygon's front is its corners' order: whatever way a sign faces, the corners put it there, its width
// level and its height up the wall.
TEST(SignLayout, CornersFaceTheSignsFront) {
    auto signs = read("# name centre front w h kind shows\n"
                      "north 17.47 10 2.35  0 -1 0  0.4 0.2 emitting 150\n"
                      "east  10 3.87 2.35   1 0 0   0.4 0.2 emitting 150 6\n"
                      "tilted 1 1 1  1 1 0  0.4 0.3 reflecting 0.8\n"
                      "floor 1 1 0  0 0 1  0.5 0.3 reflecting 0.5\n");
    ASSERT_EQ(signs.size(), 4u);
    EXPECT_EQ(signs[1].jinConstant, 6);
    EXPECT_EQ(signs[2].jinConstant, 3);
    for (const SignPlacement& s : signs) {
        std::array<dvec3, 4> c = s.corners();
        dvec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
        EXPECT_NEAR(glm::dot(n, s.front), 1, 1e-12) << s.name;
        EXPECT_NEAR(glm::length(c[1] - c[0]), s.width, 1e-12) << s.name;
        EXPECT_NEAR(glm::length(c[3] - c[0]), s.height, 1e-12) << s.name;
        EXPECT_NEAR(glm::length(0.25 * (c[0] + c[1] + c[2] + c[3]) - s.centre), 0, 1e-12) << s.name;
        if (s.name != "floor") EXPECT_NEAR(c[1].z - c[0].z, 0, 1e-12) << s.name;  // level
    }
}

TEST(SignLayout, NamesWhatIsWrong) {
    auto message = [](const std::string& text) {
        try {
            read(text);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("a 0 0 0  0 0 0  1 1 emitting 100\n"), "signs.txt:1: sign 'a': its front has no direction");
    EXPECT_EQ(message("a 0 0 0  1 0 0  1 0 emitting 100\n"), "signs.txt:1: sign 'a': width and height must be > 0");
    EXPECT_EQ(message("a 0 0 0  1 0 0  1 1 glowing 100\n"), "signs.txt:1: sign 'a': kind 'glowing' is neither emitting nor reflecting");
    EXPECT_EQ(message("a 0 0 0  1 0 0  1 1 reflecting 1.5\n"), "signs.txt:1: sign 'a': reflectance must be in (0, 1]");
    EXPECT_EQ(message("a 0 0 0  1 0 0  1 1 emitting 100\na 0 0 0  1 0 0  1 1 emitting 100\n"),
              "signs.txt:2: sign 'a': listed twice (signs.txt:1)");
    EXPECT_EQ(message("a 0 0 0  1 0 0\n").rfind("signs.txt:1: expected", 0), 0u);
    EXPECT_EQ(message("# none\n"), "signs.txt: no signs");
}

}  // namespace
}  // namespace brume
