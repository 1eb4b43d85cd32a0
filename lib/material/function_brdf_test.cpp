#include "material/function_brdf.h"

#include <gtest/gtest.h>

#include "scene_text.h"

using namespace brume;
using test::renderSceneError;

namespace {
const std::string kDir = std::string(BRUME_TEST_DATA) + "/material_functions/";
}

TEST(FunctionBrdfMaterial, BadArgumentsAreErrorsOfTheirObject) {
    test::ScopedRayPath path(kDir.c_str());
    EXPECT_EQ(renderSceneError("void plasfunc p 2 phong brdf.cal\n0\n3 .5 .5 .5\n"),
              "test.rad:1: bad arguments for plasfunc \"p\": expected at least 4 real arguments");
    EXPECT_EQ(renderSceneError("\nvoid transfunc t 2 phong brdf.cal\n0\n5 .5 .5 .5 .1 .5\n"),
              "test.rad:2: bad arguments for transfunc \"t\": expected at least 6 real arguments");
    EXPECT_EQ(renderSceneError("void metfunc m 1 phong\n0\n4 .5 .5 .5 .5\n"),
              "test.rad:1: bad arguments for metfunc \"m\": too few string arguments");
    // lightxy.dat has two dimensions: two coordinate functions are needed.
    EXPECT_EQ(renderSceneError("void metdata m 4 scaled lightxy.dat brdf.cal lightx\n0\n5 .5 .5 .5 .5 1\n"),
              "test.rad:1: bad arguments for metdata \"m\": too few string arguments");
    EXPECT_NE(renderSceneError("void plasfunc p 2 nosuchfunction brdf.cal\n0\n4 .5 .5 .5 .1\n").find("test.rad:1"),
              std::string::npos);
    EXPECT_EQ(renderSceneError("void plasfunc p 3 phong brdf.cal -s\n0\n4 .5 .5 .5 .1\n"),
              "test.rad:1: bad transform for plasfunc \"p\"");
}

// The function lights the surface from the sources only: with the source's light blocked, what is left is
// the ambient value times the whole reflectance (diffuse and specular) in the material's colour, as in
// Radiance, even for plasfunc's uncoloured specular part.
TEST(FunctionBrdfMaterial, IndirectLightSeesTheReflectanceInTheMaterialsColour) {
    test::ScopedRayPath path(kDir.c_str());
    test::TestScene s("void plasfunc p 2 phong brdf.cal\n0\n6 .5 .25 1 .2 2 20\n"
                      "p polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n");
    RenderSettings settings;
    settings.ambientValue = Spectrum(1.f);
    Integrator integrator(s.render, settings);
    Spectrum v = test::trace(integrator, dvec3(0, 0, 1), dvec3(0, 0, -1), 1).value;
    EXPECT_NEAR(v[0], 0.5, 1e-6);
    EXPECT_NEAR(v[1], 0.25, 1e-6);
    EXPECT_NEAR(v[2], 1.0, 1e-6);
}
