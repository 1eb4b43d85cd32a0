#include "render/picture_renderer.h"
#include "render/sequence.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <glm/geometric.hpp>

#include "scene_text.h"

using namespace brume;
using namespace brume::test;

namespace {

// A lamp over a floor and a ball: shading, shadows and a source seen directly.
const char* kRoom =
    "void light lamp 0 0 3 50 50 50\n"
    "lamp sphere bulb 0 0 4 1 3 3 .2\n"
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "void plastic red 0 0 5 .7 .2 .2 .02 .05\n"
    "grey polygon floor 0 0 12 -5 -2 -1 5 -2 -1 5 9 -1 -5 9 -1\n"
    "red sphere ball 0 0 4 0 4 0 1\n";

View frontView() {
    View v;
    v.vp = {0, -1, 0.5};
    v.vd = {0, 1, -0.1};
    v.vh = 60, v.vv = 45;
    return v;
}

PictureSettings exact(int x, int y) {
    PictureSettings p;
    p.xres = x, p.yres = y;
    p.jitter = 0, p.sampleSpacing = 1;
    return p;
}

}  // namespace

// Radiance's normaspect, numbers from Radiance 6.1's rpict (-x 16 -y 8 -vh 90 -vv 45 -pa .5 gives 10 x 8;
// -pa 0 keeps 9 x 8 with PIXASPECT=1.125; -pa 1 on 16 x 8 square views gives 8 x 8).
TEST(PictureRenderer, FitsTheResolutionToTheViewAsRadiance) {
    View v;
    PictureSettings p;
    p.xres = 16, p.yres = 8, p.pixelAspect = 1;
    fitResolution(v, p);
    EXPECT_EQ(p.xres, 8);
    EXPECT_EQ(p.yres, 8);
    v.vh = 90;
    p.xres = 16, p.yres = 8, p.pixelAspect = .5;
    fitResolution(v, p);
    EXPECT_EQ(p.xres, 10);
    EXPECT_EQ(p.yres, 8);
    v.vh = 45;
    p.xres = 9, p.yres = 8, p.pixelAspect = 0;
    fitResolution(v, p);
    EXPECT_EQ(p.xres, 9);
    EXPECT_DOUBLE_EQ(p.pixelAspect, 1.125);
}

// The promise rpict's man page makes: a pixel is exactly what rtrace gives for the ray vwrays writes for it
// (its point at the pixel's centre with -pj 0, its index in scanline order seeding its samples).
TEST(PictureRenderer, APixelIsTheIntegratorsValueOnItsRay) {
    TestScene t(kRoom);
    RenderSettings s = fixedSeed();
    Sequence sequence(t.scene, t.render, s);
    View v = frontView();
    PictureSettings p = exact(13, 7);  // odd sizes: no symmetry hides a swapped axis
    RenderedPicture r = renderPicture(sequence, v, 0, p);
    ASSERT_EQ(r.picture.width, 13);
    ASSERT_EQ(r.picture.height, 7);
    for (int row = 0; row < 7; ++row)
        for (int x = 0; x < 13; ++x) {
            auto ray = v.ray((x + 0.5) / 13, (7 - 1 - row + 0.5) / 7);
            ASSERT_TRUE(ray);
            RayRecord rec = test::trace(sequence.integrator(), ray->org, ray->dir, uint64_t(row) * 13 + x);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(r.picture.at(x, row)[c], rec.value[c]) << x << "," << row;
        }
}

// The top of the picture looks up: the lamp (above the view axis) appears in the upper half, the floor in the
// lower rows, and the left of the picture is the left of the view.
TEST(PictureRenderer, RowsRunDownFromTheTop) {
    TestScene t(kRoom);
    Sequence sequence(t.scene, t.render, fixedSeed());
    View v = frontView();
    v.vd = {0.25, 1, 0.6};  // looking up at the lamp, at x = 1: right of centre
    RenderedPicture r = renderPicture(sequence, v, 0, exact(32, 32));
    int brightestX = 0, brightestRow = 0;
    for (int row = 0; row < 32; ++row)
        for (int x = 0; x < 32; ++x)
            if (r.picture.at(x, row)[0] > r.picture.at(brightestX, brightestRow)[0]) brightestX = x, brightestRow = row;
    EXPECT_FLOAT_EQ(r.picture.at(brightestX, brightestRow)[0], 50.f);
    dvec3 d = v.ray((brightestX + 0.5) / 32, (31 - brightestRow + 0.5) / 32)->dir;
    dvec3 toLamp = glm::normalize(dvec3(1, 3, 3) - v.vp);
    EXPECT_GT(glm::dot(d, toLamp), std::cos(0.2 / glm::length(dvec3(1, 3, 3) - v.vp) + 0.05));
}

// -ps > 1: where the first-pass samples agree (a uniform glow all round, seen from inside) every pixel is
// interpolated from them exactly; where they differ, pixels are traced, so they equal the fully traced ones.
TEST(PictureRenderer, AdaptiveSamplingInterpolatesOnlyWhereSamplesAgree) {
    TestScene glow("void glow g 0 0 4 2 3 4 0\ng sphere sky 0 0 4 0 0 0 -100\n");
    Sequence uniform(glow.scene, glow.render, fixedSeed());
    PictureSettings p = exact(148, 92);
    p.sampleSpacing = 4;
    RenderedPicture a = renderPicture(uniform, frontView(), 0, p);
    for (int row = 0; row < 92; ++row)
        for (int x = 0; x < 148; ++x) EXPECT_FLOAT_EQ(a.picture.at(x, row)[1], 3.f);

    TestScene t(kRoom);
    Sequence sequence(t.scene, t.render, fixedSeed());
    RenderedPicture full = renderPicture(sequence, frontView(), 0, exact(148, 92));
    RenderedPicture adaptive = renderPicture(sequence, frontView(), 0, p);
    int same = 0;
    for (size_t i = 0; i < full.picture.pixels.size(); ++i) same += adaptive.picture.pixels[i] == full.picture.pixels[i];
    EXPECT_GT(same, int(full.picture.pixels.size() / 3));  // the edges and the ball's shading are traced
    EXPECT_LT(same, int(full.picture.pixels.size()));      // the flat floor and the black sky are not
}

// -ps > 1 refines as Radiance's rpict: a tile whose corners differ has its middles traced and is split, level
// by level, so a smooth gradient (a floor under a lamp, no shadow) costs a few samples per tile, not the
// whole tile, and every interpolated pixel stays within the threshold of the traced one.
TEST(PictureRenderer, AdaptiveSamplingRefinesGradientsByHalves) {
    TestScene t("void light lamp 0 0 3 50 50 50\nlamp sphere bulb 0 0 4 0 2 1.5 .05\n"
                "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon floor 0 0 12 -9 -9 -1 9 -9 -1 9 9 -1 -9 9 -1\n");
    Sequence sequence(t.scene, t.render, fixedSeed());
    View down;  // the floor fills the view, under a lamp behind the eye
    down.vp = {0, 2, 1}, down.vd = {0, 0, -1}, down.vu = {0, 1, 0};
    down.vh = 60, down.vv = 45;
    PictureSettings p = exact(64, 48);
    RenderedPicture full = renderPicture(sequence, down, 0, p);
    p.sampleSpacing = 8;
    RenderedPicture adaptive = renderPicture(sequence, down, 0, p);
    int traced = 0, busyTiles = 0;
    double worst = 0;
    for (int row = 0; row < 48; ++row)
        for (int x = 0; x < 64; ++x) {
            float a = adaptive.picture.at(x, row)[1], f = full.picture.at(x, row)[1];
            traced += a == f;
            worst = std::max(worst, std::abs(double(a) / f - 1));
        }
    for (int row = 0; row + 8 < 48; row += 8)
        for (int x = 0; x + 8 < 64; x += 8) {
            float a = full.picture.at(x, row)[1], b = full.picture.at(x + 8, row + 8)[1];
            busyTiles += std::abs(a / b - 1) > p.sampleThreshold;
        }
    EXPECT_GT(busyTiles, 10);            // the gradient is steep enough to split tiles
    EXPECT_LT(traced, 64 * 48 / 3);      // tracing them whole would trace nearly every pixel
    EXPECT_LT(worst, p.sampleThreshold);  // linear between corners that agree within the threshold
}

// -ps > 1 also refines where distances differ, as Radiance's rpict: a pole of the same glow as the wall behind
// it looks the same in colour, yet every pixel's distance is right, pole and wall, not a blend of the two.
TEST(PictureRenderer, AdaptiveSamplingRefinesWhereDistancesDiffer) {
    TestScene t("void glow g 0 0 4 1 1 1 0\ng polygon wall 0 0 12 -20 5 -20 20 5 -20 20 5 20 -20 5 20\n"
                "g cylinder pole 0 0 7 0 2 -9 0 2 9 .15\n");
    Sequence sequence(t.scene, t.render, fixedSeed());
    PictureSettings p = exact(64, 48);
    p.depth = true;
    RenderedPicture full = renderPicture(sequence, frontView(), 0, p);
    p.sampleSpacing = 8;
    RenderedPicture adaptive = renderPicture(sequence, frontView(), 0, p);
    int wrong = 0;
    for (size_t i = 0; i < full.depth.size(); ++i) wrong += std::abs(adaptive.depth[i] / full.depth[i] - 1) > 0.02;
    EXPECT_EQ(wrong, 0);
}

// -u-: the same picture whatever the number of threads, with jitter on, with the irradiance cache or without.
TEST(PictureRenderer, SamePictureOnAnyNumberOfThreads) {
    TestScene t(kRoom);
    RenderSettings s = fixedSeed();
    s.ambientBounces = 1, s.ambientDivisions = 16;
    PictureSettings p;
    p.xres = p.yres = 24;
    fitResolution(frontView(), p);
    // Each with its own irradiance cache (a second picture by one integrator reuses the first's records).
    auto render = [&](int threads) {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
        Sequence sequence(t.scene, t.render, s);
        return renderPicture(sequence, frontView(), 0, p).picture.pixels;
    };
    EXPECT_EQ(render(1), render(2));
    s.ambientAccuracy = 0;  // path tracing
    EXPECT_EQ(render(1), render(2));
}

// A hemispherical fisheye sees nothing beyond 90° off axis: the corners of its square picture stay black;
// depth is the distance to what a pixel sees.
TEST(PictureRenderer, FisheyeCornersAreBlackAndDepthIsDistance) {
    TestScene glow("void glow g 0 0 4 1 1 1 0\ng sphere sky 0 0 4 0 0 0 -10\n");
    Sequence sequence(glow.scene, glow.render, fixedSeed());
    View v;
    v.type = kHemispherical, v.vh = v.vv = 180;
    PictureSettings p = exact(16, 16);
    p.depth = true;
    RenderedPicture r = renderPicture(sequence, v, 0, p);
    EXPECT_EQ(r.picture.at(0, 0)[0], 0.f);
    EXPECT_EQ(r.picture.at(15, 15)[0], 0.f);
    EXPECT_FLOAT_EQ(r.picture.at(8, 8)[0], 1.f);
    ASSERT_EQ(r.depth.size(), 256u);
    EXPECT_NEAR(r.depth[8 * 16 + 8], 10.0, 1e-4);
}
