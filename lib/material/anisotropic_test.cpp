#include "material/anisotropic.h"

#include <gtest/gtest.h>

#include "material/testing.h"
#include "pattern/pattern_evaluator.h"
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

namespace {

// Light arriving along `dir` on a surface of normal +z of the scene's first object, the material `text`, with
// what its function files need at the hit.
struct AnisotropicHit {
    AnisotropicHit(const std::string& text, const dvec3& dir)
        : scene(text + "m polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n"), evaluator(scene.render.modifiers()) {
        pattern = PatternHit{dvec3(0), dir, dvec3(0, 0, 1), 1.0};
        shading = Shading{dvec3(0), dvec3(0, 0, 1), dir, -dir.z, false, true, 1.0};
        shading.hit = &pattern;
        shading.evaluator = &evaluator;
    }
    const GeneralLobe& lobe() {
        Lobes lobes;
        EXPECT_TRUE(scene.render.material(0)->scatter(shading, lobes));
        EXPECT_TRUE(lobes.general && lobes.sampleGeneral);
        return *lobes.general;
    }
    test::TestScene scene;
    PatternEvaluator evaluator;
    PatternHit pattern;
    Shading shading;
};

}  // namespace

// The sampled lobe of plastic2 (reflection alone) and of trans2 (reflection or transmission, drawn by their
// brightness), seen along the normal and at 80° from it: draws follow the lobe's pdf (chi-square: 2×10⁵ draws in
// 24×48 cells about the normal, the horizon on a cell edge: 10% off over a tenth of the draws fails; each draw
// evaluates the orientation's expressions three times, so more cost seconds).
TEST(AnisotropicMaterial, DrawsFollowItsPdf) {
    for (const char* material : {"void plastic2 m 4 1 0.2 0 .\n0\n6 .5 .5 .5 .3 .1 .25\n",
                                 "void trans2 m 4 1 0.2 0 .\n0\n8 .6 .5 .4 .3 .15 .3 .8 .5\n"})
        for (double view : {0.0, 80.0}) {
            double t = view * std::numbers::pi / 180;
            AnisotropicHit hit(material, dvec3(0.6 * std::sin(t), 0.8 * std::sin(t), -std::cos(t)));
            SCOPED_TRACE(testing::Message() << material << "view at " << view << "°");
            material::testing::expectDrawsFollowPdf(hit.lobe(), hit.shading,
                                                    {.draws = 200'000, .rings = 24, .sectors = 48});
        }
}
