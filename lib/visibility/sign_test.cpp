#include "visibility/sign.h"

#include <gtest/gtest.h>

#include "scene_text.h"
#include "util/error.h"

namespace brume {
namespace {

TEST(Sign, LatticePointsCoverTheSignAndTheBandAroundIt) {
    const char* text = "void glow green 0 0 4 0 1 0 0\n"
                       "green polygon exit 0 0 12  4 -0.3 2  4 -0.3 2.15  4 0.3 2.15  4 0.3 2\n";
    Scene scene = test::sceneFromText(text);
    Sign s = signFromScene(scene, "exit", SignKind::Emitting, 8);
    EXPECT_NEAR(s.shape.area, 0.09, 1e-12);
    EXPECT_NEAR(glm::length(s.centre - dvec3(4, 0, 2.075)), 0, 1e-12);
    std::vector<dvec3> on = pointsOnSign(s, 64);
    ASSERT_EQ(on.size(), 64u);
    dvec3 mean(0);
    for (const dvec3& p : on) {
        EXPECT_TRUE(insidePolygon(s.shape, p));
        mean += p / 64.0;
    }
    EXPECT_LT(glm::length(mean - s.centre), 0.01);  // a lattice's mean: within a sixtieth of the sign
    std::vector<dvec3> around = pointsAroundSign(s, 64, 1.5);
    EXPECT_GE(around.size(), 58u);
    EXPECT_LE(around.size(), 70u);
    mean = dvec3(0);
    for (const dvec3& p : around) {
        EXPECT_FALSE(insidePolygon(s.shape, p));
        EXPECT_LE(std::abs(p.y), 0.45 + 1e-12);
        EXPECT_LE(std::abs(p.z - 2.075), 0.1125 + 1e-12);
        mean += p / double(around.size());
    }
    EXPECT_LT(glm::length(mean - s.centre), 0.02);
}

TEST(Sign, NamesWhatIsWrong) {
    Scene scene = test::sceneFromText("void glow g 0 0 4 1 1 1 0\ng polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n"
                                      "g polygon a 0 0 9 0 0 1 1 0 1 0 1 1\ng sphere s 0 0 4 0 0 0 1\n");
    auto message = [&](const std::string& name) {
        try {
            signFromScene(scene, name, SignKind::Reflecting, 3);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("a"), "test.rad:2: sign 'a': two polygons have this name (test.rad:3)");
    EXPECT_EQ(message("s"), "sign 's': no polygon of this name in the scene");
    EXPECT_EQ(message("b"), "sign 'b': no polygon of this name in the scene");
}

}  // namespace
}  // namespace brume
