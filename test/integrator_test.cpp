// How the integrator counts light: each path once, whatever route it takes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene_text.h"

using namespace brume;
using namespace brume::test;

namespace {
// The sun (10⁵ W/sr/m², 0.5°) above a clear pane of transmissivity 0.9: E = L Ω T, T from the
// multiple-reflection formula of glass at normal incidence (n = 1.52): 0.8262.
const char* kSunThroughGlass =
    "void light solar 0 0 3 1e5 1e5 1e5\n"
    "solar source sun 0 0 4 0 0 1 0.5\n"
    "void glass pane 0 0 3 .9 .9 .9\n"
    "pane polygon win 0 0 12 -1 -1 1 1 -1 1 1 1 1 -1 1 1\n";

double sunThroughGlass() {
    double omega = 2 * std::numbers::pi * (1 - std::cos(0.25 * std::numbers::pi / 180));
    double r = std::pow((1 - 1.52) / (1 + 1.52), 2), tau = 0.9;
    return 1e5 * omega * (1 - r) * (1 - r) * tau / (1 - r * r * tau * tau);
}
}  // namespace

// Tolerance 0.1%: the sun's cone is sampled exactly; only the cosine varies inside it (< 1e-5).
TEST(Integrator, SunThroughGlassReachesASensorOnceWhateverTheBounces) {
    TestScene t(kSunThroughGlass);
    for (int bounces : {0, 1, 3}) {
        RenderSettings s = fixedSeed();
        s.ambientBounces = bounces;
        s.ambientDivisions = 64;
        Integrator integrator(t.render, s);
        EXPECT_NEAR(test::irradiance(integrator, dvec3(0), dvec3(0, 0, 1), 0).value[0], sunThroughGlass(), 1e-3 * sunThroughGlass())
            << "-ab " << bounces;
    }
}

TEST(Integrator, ZeroAmbientDivisionsKeepDirectLight) {
    TestScene t(kSunThroughGlass);
    RenderSettings s = fixedSeed();
    s.ambientBounces = 2;
    s.ambientDivisions = 0;
    Integrator integrator(t.render, s);
    EXPECT_NEAR(test::irradiance(integrator, dvec3(0), dvec3(0, 0, 1), 0).value[0], sunThroughGlass(), 1e-3 * sunThroughGlass());
}

// -dv- hides sources from the rays that look at them, not the light a glossy surface reflects of them.
TEST(Integrator, InvisibleSourcesStillLightGlossySurfaces) {
    TestScene t("void light lum 0 0 3 100 100 100\n"
                "lum sphere bulb 0 0 4 0 0 2 0.2\n"
                "void metal shiny 0 0 5 .8 .8 .8 .9 .05\n"
                "shiny polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n");
    RenderSettings visible = fixedSeed(), hidden = fixedSeed();
    hidden.directVisible = false;
    Integrator a(t.render, visible), b(t.render, hidden);
    // Looking at the floor where it mirrors the bulb (a highlight), averaged over many rays.
    double sumA = 0, sumB = 0;
    for (int i = 0; i < 400; ++i) {
        dvec3 org(-1, 0, 1), dir = glm::normalize(dvec3(1, 0, -1));
        sumA += test::trace(a, org, dir, i).value[0];
        sumB += test::trace(b, org, dir, i).value[0];
    }
    EXPECT_GT(sumA, 0);
    EXPECT_NEAR(sumB, sumA, 0.05 * sumA);
    EXPECT_EQ(test::trace(b, dvec3(0), dvec3(0, 0, 1), 0).value[0], 0.f);
    EXPECT_EQ(test::trace(a, dvec3(0, 0, 0.5), dvec3(0, 0, 1), 0).value[0], 100.f);
}

// An antimatter sphere cuts a hole in an opaque ceiling: light passes there and nowhere else.
TEST(Integrator, AntimatterCutsHolesInTheModifiersItNames) {
    const std::string scene =
        "void light lum 0 0 3 100 100 100\n"
        "lum sphere bulb 0 0 4 0 0 2 0.1\n"
        "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
        "grey polygon ceiling 0 0 12 -5 -5 1 -5 5 1 5 5 1 5 -5 1\n";
    const double expected = std::numbers::pi * 100 * 0.05 * 0.05;  // πL(r/d)², d = 2
    RenderSettings s = fixedSeed();
    TestScene closed(scene);
    EXPECT_EQ(test::irradiance(Integrator(closed.render, s), dvec3(0), dvec3(0, 0, 1), 0).value[0], 0.f);
    TestScene holed(scene + "void antimatter hole 1 grey 0 0\nhole sphere cut 0 0 4 0 0 1 0.5\n");
    Integrator integrator(holed.render, s);
    EXPECT_NEAR(test::irradiance(integrator, dvec3(0), dvec3(0, 0, 1), 0).value[0], expected, 0.005 * expected);
    // Looking up through the hole, a ray sees the bulb; the antimatter surface itself is invisible.
    EXPECT_EQ(test::trace(integrator, dvec3(0), dvec3(0, 0, 1), 0).value[0], 100.f);
}

namespace {
// A sphere lamp under a flat mirror ceiling: a sensor off to the side sees the lamp and, in the mirror,
// its image twice as high (each fully visible), E = πL Σ (r/d)² cos β, the image's term times ρ.
const char* kLampUnderMirror =
    "void light lum 0 0 3 100 100 100\n"
    "lum sphere bulb 0 0 4 0 0 2 0.5\n"
    "void mirror silver 0 0 3 .8 .8 .8\n"
    "silver polygon ceiling 0 0 12 -10 -10 3 -10 10 3 10 10 3 10 -10 3\n";

double lampAndImage() {
    double direct = std::numbers::pi * 100 * (0.5 * 0.5 / 13) * (2 / std::sqrt(13.0));
    double image = 0.8 * std::numbers::pi * 100 * (0.5 * 0.5 / 25) * 0.8;
    return direct + image;
}
}  // namespace

// Tolerance 0.5%: both cones are sampled exactly; what varies is the cosine across them.
TEST(Integrator, MirrorImagesOfSourcesLightSurfacesWithoutBounces) {
    TestScene t(kLampUnderMirror);
    RenderSettings s = fixedSeed();
    s.sourceSubdivision = 0.02;
    Integrator integrator(t.render, s);
    EXPECT_NEAR(meanIrradiance(integrator, dvec3(3, 0, 0), dvec3(0, 0, 1), 8), lampAndImage(), 0.005 * lampAndImage());
    s.directRelays = 0;  // -dr 0: the image is not a source; only interreflection paths could find it
    Integrator without(t.render, s);
    double lampOnly = lampAndImage() - 0.8 * std::numbers::pi * 100 * (0.5 * 0.5 / 25) * 0.8;
    EXPECT_NEAR(meanIrradiance(without, dvec3(3, 0, 0), dvec3(0, 0, 1), 8), lampOnly, 0.005 * lampOnly);
}

// A shadow ray to a source's mirror image goes to the mirror and on in the image ray's direction; a dielectric
// slab on the way to the mirror shifts it sideways, so here it goes on past the small lamp into the ceiling:
// no light. (The lamp's direct light is stopped by a plate.)
TEST(Integrator, ShadowRaysShiftedOnTheWayToAMirrorMissTheImage) {
    const std::string room = "void light lum 0 0 3 100 100 100\n"
                             "lum polygon lamp 0 0 12 -.05 -.05 2 -.05 .05 2 .05 .05 2 .05 -.05 2\n"
                             "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                             "grey polygon ceiling 0 0 12 -5 -5 2.01 -5 5 2.01 5 5 2.01 5 -5 2.01\n"
                             "grey polygon plate 0 0 12 -.5 -.5 1 -.5 .5 1 .5 .5 1 .5 -.5 1\n"
                             "void mirror silver 0 0 3 .8 .8 .8\n"
                             "silver polygon wall 0 0 12 1 -1 0 1 -1 3 1 1 3 1 1 0\n";
    TestScene bare(room);
    EXPECT_GT(test::irradiance(Integrator(bare.render, fixedSeed()), dvec3(0), dvec3(0, 0, 1), 0).value[0], 0.f);
    TestScene slab(room + "void dielectric crown 0 0 5 1 1 1 1.5 0\n"
                          "crown polygon near 0 0 12 .3 -5 -1 .3 -5 .9 .3 5 .9 .3 5 -1\n"
                          "crown polygon far 0 0 12 .8 -5 -1 .8 5 -1 .8 5 .9 .8 -5 .9\n");
    EXPECT_EQ(test::irradiance(Integrator(slab.render, fixedSeed()), dvec3(0), dvec3(0, 0, 1), 0).value[0], 0.f);
}

// With -ab, paths that reach the lamp through the mirror are counted once: by its image when -dr is on,
// by the paths themselves when it is off. Tolerance 3%: the -dr 0 estimate rests on rare path hits.
TEST(Integrator, PathsThroughMirrorsAreCountedOnceWithOrWithoutImages) {
    TestScene t(kLampUnderMirror);
    RenderSettings s = fixedSeed();
    s.ambientBounces = 1;
    s.ambientDivisions = 8192;
    Integrator with(t.render, s);
    s.directRelays = 0;
    Integrator without(t.render, s);
    double a = meanIrradiance(with, dvec3(3, 0, 0), dvec3(0, 0, 1), 8);
    double b = meanIrradiance(without, dvec3(3, 0, 0), dvec3(0, 0, 1), 8);
    EXPECT_NEAR(a, lampAndImage(), 0.005 * lampAndImage());
    EXPECT_NEAR(b, a, 0.03 * a);
}

// A sensor right under the edge of a plate's shadow sees half of the sun's disc: 64 stratified shadow rays
// put each estimate within 5 % of half the sun (one ray would read all or none).
TEST(Integrator, ASensorInThePenumbraReadsItsShareOfTheSun) {
    TestScene t("void light solar 0 0 3 1e5 1e5 1e5\n"
                "solar source sun 0 0 4 0 0 1 0.5\n"
                "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                "grey polygon plate 0 0 12 -5 -5 1 0 -5 1 0 5 1 -5 5 1\n");
    const double half = 0.5 * 1e5 * 2 * std::numbers::pi * (1 - std::cos(0.25 * std::numbers::pi / 180));
    Integrator integrator(t.render, fixedSeed());
    for (int i = 0; i < 20; ++i)
        EXPECT_NEAR(test::irradiance(integrator, dvec3(0), dvec3(0, 0, 1), uint64_t(i)).value[0], half, 0.05 * half) << i;
}

// A sensor facing a glass wall, a sun behind it: the sensor's only light is the sun's reflection in the glass,
// which no next-event estimation reaches. A view ray sees the reflected sun; the sensor's diffuse paths find a
// small sun there by rare luck only (a 2° sun: about six rays of the 81,920 here) and drop it, as Radiance drops
// every source met so; a large source (a 20° disc) is found often and counted.
TEST(Integrator, SmallSourcesOnlyChanceFindsAfterADiffuseBounceAreDropped) {
    auto scene = [](double angle) {
        return "void light solar 0 0 3 1e4 1e4 1e4\n"
               "solar source sun 0 0 4 0 -1 1 " + std::to_string(angle) + "\n"
               "void glass pane 0 0 3 .9 .9 .9\n"
               "pane polygon wall 0 0 12 -50 1 -50 50 1 -50 50 1 50 -50 1 50\n";
    };
    RenderSettings s = fixedSeed();
    s.ambientBounces = 1, s.ambientDivisions = 4096;
    TestScene small(scene(2)), large(scene(20));
    Integrator a(small.render, s), b(large.render, s);
    const dvec3 towardReflection = glm::normalize(dvec3(0, 1, 1));
    EXPECT_GT(test::trace(a, dvec3(0), towardReflection, 0).value[0], 100.f);  // the glass reflects ~5 %: ~500
    double smallSum = 0, largeSum = 0;
    for (int i = 0; i < 20; ++i) {
        smallSum += test::irradiance(a, dvec3(0), dvec3(0, 1, 0), uint64_t(i)).value[0];
        largeSum += test::irradiance(b, dvec3(0), dvec3(0, 1, 0), uint64_t(i)).value[0];
    }
    EXPECT_EQ(smallSum, 0);
    EXPECT_GT(largeSum, 0);
}

// Shadow rays skip the surface-by-surface walk only at surfaces that stop every one of them; anything that
// passes light, depends on the source, is cut away or varies from hit to hit is left to the walk.
TEST(RenderScene, OnlyPlainlyOpaqueSurfacesBlockShadowRaysOutright) {
    const char* types[] = {"void plastic grey 0 0 5 .5 .5 .5 0 0",
                           "void glass clear 0 0 3 .9 .9 .9",
                           "void trans sheer 0 0 7 .5 .5 .5 0 0 .5 1",    // pure specular transmission
                           "void trans frosted 0 0 7 .5 .5 .5 0 .1 .5 1",  // rough: blocks shadow rays
                           "void illum window 1 grey 0 3 1 1 1",
                           "void light lamp 0 0 3 10 10 10",
                           "void plastic cutaway 0 0 5 .5 .5 .5 0 0",
                           "void antimatter hole 1 cutaway 0 0",
                           "void mirror silver 0 0 3 .8 .8 .8"};
    std::string text;
    for (const char* t : types) text += std::string(t) + "\n";
    const char* surfaces[] = {"grey", "clear", "sheer", "frosted", "window", "lamp", "cutaway", "hole", "silver"};
    const bool blocks[] = {true, false, false, true, false, true, false, false, true};
    for (int i = 0; i < 9; ++i) {
        std::string z = std::to_string(i + 1);
        text += std::string(surfaces[i]) + " polygon p" + z + " 0 0 12 0 0 " + z + " 1 0 " + z + " 1 1 " + z + " 0 1 " + z + "\n";
    }
    TestScene plain(text);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(plain.render.blocksShadows(SurfaceId{i}), blocks[i]) << surfaces[i];
    EXPECT_TRUE(plain.render.blockersDecide());
    // Patterns draw a random number where the walk crosses them, dielectrics bend it: then only the walk
    // knows whether what lies before a blocker matters.
    TestScene patterned(text + "void brightfunc dots 2 Dx . 0 0\ndots plastic dotted 0 0 5 .5 .5 .5 0 0\n"
                               "dotted polygon p10 0 0 12 0 0 10 1 0 10 1 1 10 0 1 10\n");
    EXPECT_FALSE(patterned.render.blocksShadows(SurfaceId{9}));
    EXPECT_FALSE(patterned.render.blockersDecide());
    EXPECT_FALSE(TestScene(text + "void dielectric water 0 0 5 .9 .9 .9 1.33 0\n").render.blockersDecide());
    // A patterned sky is no surface a shadow ray crosses.
    EXPECT_TRUE(TestScene(text + "void brightfunc skyfunc 2 Dx . 0 0\nskyfunc glow skyglow 0 0 4 1 1 1 0\n"
                                 "skyglow source sky 0 0 4 0 0 1 180\n").render.blockersDecide());
}
