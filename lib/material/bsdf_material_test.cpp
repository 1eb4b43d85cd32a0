#include "material/bsdf_material.h"

#include <gtest/gtest.h>

#include "material/testing.h"
#include "scene_text.h"

namespace brume {
namespace {

const std::string kDir = std::string(BRUME_TEST_DATA) + "/bsdf";

std::string errorOf(const std::string& text) {
    test::ScopedRayPath path(kDir.c_str());
    try {
        Scene scene = test::sceneFromText(text);
        RenderScene render(scene, MaterialSettings{});
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(BsdfMaterial, BadArgumentsSayWhereAndWhat) {
    EXPECT_EQ(errorOf("void BSDF b 6 0 prism_quarter.xml 0 1 0 . 0 2 1 1"),
              "test.rad:1: bad arguments for BSDF \"b\": expected 0, 3, 6 or 9 reals");
    EXPECT_EQ(errorOf("void BSDF b 5 0 prism_quarter.xml 0 1 0 0 0"),
              "test.rad:1: bad arguments for BSDF \"b\": expected 6 or more strings");
    EXPECT_EQ(errorOf("\nvoid BSDF b 6 0 none.xml 0 1 0 . 0 0"), "test.rad:2: cannot find BSDF file \"none.xml\" for b");
    EXPECT_EQ(errorOf("void BSDF b 6 0 prism_quarter.xml 0 Py 0 . 0 0"),
              "test.rad:1: bad arguments for BSDF \"b\": \"Py\" varies over the surface; Brume takes only constant "
              "thickness and up vectors");
    EXPECT_EQ(errorOf("void BSDF b 6 0 prism_quarter.xml 0 1 0 . 0 9 .1 .1 .1 .1 .1 .1 .1 .1 .1"), "no error");
}

TEST(BsdfMaterial, UpVectorTurnsTheLobe) {
    test::ScopedRayPath path(kDir.c_str());
    auto value = [&](const char* up, const ObjectFrame* object = nullptr) {
        test::TestScene t(std::string("void BSDF b 6 0 prism_quarter.xml ") + up + " . 0 0\n"
                          "b polygon p 0 0 12 -1 -1 0 -1 1 0 1 1 0 1 -1 0\n");
        const Material* m = t.render.material(0);
        Shading s{dvec3(0), dvec3(0, 0, -1), dvec3(0, 0, 1), 1.0, false, true, 1.0};
        s.object = object;
        Lobes lobes;
        EXPECT_TRUE(m->scatter(s, lobes));
        EXPECT_TRUE(lobes.general && lobes.sampleGeneral);  // transmission above -st 0.15
        return lobes.general->response(s, glm::normalize(dvec3(0, 0.3, 1)))[0];
    };
    // prism_quarter.xml bends transmitted light toward the up vector: light from +y above, going toward −y,
    // is bent back toward the straight-down view when up is +y, further away when up is −y.
    EXPECT_GT(value("0 1 0"), 2 * value("0 -1 0"));
    // On a surface of an instance or mesh turned half a turn about z, up turns with it (Radiance's object
    // transform): +y in the object is −y in the world.
    ObjectFrame halfTurn;
    halfTurn.toWorld.matrix = glm::dmat4(glm::dvec4(-1, 0, 0, 0), glm::dvec4(0, -1, 0, 0), glm::dvec4(0, 0, 1, 0),
                                         glm::dvec4(0, 0, 0, 1));
    halfTurn.toObject = halfTurn.toWorld.inverse();
    EXPECT_FLOAT_EQ(value("0 1 0", &halfTurn), value("0 -1 0"));
}

// The Klems lobe of prism_quarter.xml seen from the front along the normal and at 60°, and from the back at 40°:
// draws (reflection or transmission, by their sampled albedos; a patch, then uniform in projected solid angle
// in it) follow its pdf (chi-square: 5×10⁴ draws in 20×40 cells about the normal, the horizon on a cell edge: 13%
// off over a tenth of the draws fails; the pdf averages 16 jittered views and the cells its patches' edges cross
// are integrated finely, so more draws cost seconds).
TEST(BsdfMaterial, KlemsDrawsFollowItsPdf) {
    test::ScopedRayPath path(kDir.c_str());
    test::TestScene t(
        "void BSDF b 6 0 prism_quarter.xml 0 1 0 . 0 0\nb polygon p 0 0 12 -1 -1 0 -1 1 0 1 1 0 1 -1 0\n");
    for (auto [view, backside] : {std::pair{0.0, false}, std::pair{60.0, false}, std::pair{40.0, true}}) {
        double a = view * std::numbers::pi / 180;
        dvec3 dir(0.6 * std::sin(a), -0.8 * std::sin(a), -std::cos(a));  // toward the surface, normal turned to it
        Shading s{dvec3(0), dvec3(0, 0, 1), dir, std::cos(a), backside, true, 1.0};
        Lobes lobes;
        ASSERT_TRUE(t.render.material(0)->scatter(s, lobes));
        ASSERT_TRUE(lobes.general && lobes.sampleGeneral);
        SCOPED_TRACE(testing::Message() << "view at " << view << "°" << (backside ? " from the back" : ""));
        material::testing::expectDrawsFollowPdf(*lobes.general, s, {.draws = 50'000, .rings = 20, .sectors = 40});
    }
}

}  // namespace
}  // namespace brume
