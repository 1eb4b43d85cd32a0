#include "material/anisotropic.h"

#include <gtest/gtest.h>

#include "scene_text.h"

using namespace brume;

using test::renderSceneError;

TEST(AnisotropicMaterial, BadArgumentsAreErrorsOfTheirObject) {
    EXPECT_EQ(renderSceneError("void plastic2 p 4 1 0 0 .\n0\n5 .5 .5 .5 .1 .2\n"),
              "test.rad:1: bad arguments for plastic2 \"p\": expected 6 real arguments, got 5");
    EXPECT_EQ(renderSceneError("\nvoid trans2 t 4 1 0 0 .\n0\n6 .5 .5 .5 .1 .2 .3\n"),
              "test.rad:2: bad arguments for trans2 \"t\": expected 8 real arguments, got 6");
    EXPECT_EQ(renderSceneError("void metal2 m 4 1 0 0 .\n0\n6 .5 .5 .5 .9 0 .2\n"),
              "test.rad:1: bad arguments for metal2 \"m\": roughness too small");
    EXPECT_EQ(renderSceneError("void metal2 m 3 1 0 0\n0\n6 .5 .5 .5 .9 .1 .2\n"),
              "test.rad:1: bad arguments for metal2 \"m\": too few string arguments");
    EXPECT_EQ(renderSceneError("void metal2 m 5 1 0 0 . -rz\n0\n6 .5 .5 .5 .9 .1 .2\n"),
              "test.rad:1: bad transform for metal2 \"m\"");
    EXPECT_NE(renderSceneError("void metal2 m 4 1 0 nosuchname .\n0\n6 .5 .5 .5 .9 .1 .2\n").find("test.rad:1"), std::string::npos);
}

// A metal2 lit from one side: its highlight is longer along the smoother direction. Seen at the mirror
// angle of a source turned about v (across u, the rougher direction here) it stays brighter than turned
// about u, and rotating u by 90° swaps the two.
TEST(AnisotropicMaterial, HighlightStretchesAlongTheSmootherDirection) {
    auto value = [](const char* u, const dvec3& dir) {
        MaterialSettings traceNothing{1, true};  // -st 1: the highlights alone
        test::TestScene s(std::string("void light l 0 0 3 1e4 1e4 1e4\nl sphere s 0 0 4 0 0 2 .02\n"
                                      "void metal2 m 4 ") + u + " .\n0\n6 .8 .8 .8 1 .3 .05\n"
                                      "m polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n",
                          traceNothing);
        RenderSettings settings;
        settings.materials = traceNothing;
        Integrator integrator(s.render, settings);
        return double(test::trace(integrator, -dir * 2.0, dir, 1).value[0]);
    };
    dvec3 alongX = glm::normalize(dvec3(0.3, 0, -1)), alongY = glm::normalize(dvec3(0, 0.3, -1));
    EXPECT_GT(value("1 0 0", alongX), 3 * value("1 0 0", alongY));
    EXPECT_GT(value("0 1 0", alongY), 3 * value("0 1 0", alongX));
}
