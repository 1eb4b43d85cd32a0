#include "render/small_sources.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/picture_renderer.h"
#include "render/sequence.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;

namespace {

// The light a picture collects from a source: each pixel's radiance times the solid angle the pixel spans
// (a perspective view's pixel at image point (x, y) spans Δx Δy · hn · vn · cos³θ).
double collected(const Picture& p, const View& v) {
    double hn = 2 * std::tan(v.vh * M_PI / 360), vn = 2 * std::tan(v.vv * M_PI / 360), sum = 0;
    for (int row = 0; row < p.height; ++row)
        for (int x = 0; x < p.width; ++x) {
            double a = ((x + 0.5) / p.width - 0.5) * hn, b = ((p.height - row - 0.5) / p.height - 0.5) * vn;
            double cos3 = std::pow(1 + a * a + b * b, -1.5);
            sum += p.at(x, row)[0] * cos3 * hn * vn / (p.width * p.height);
        }
    return sum;
}

View lookingAt(const dvec3& target) {
    View v;
    v.vd = target;
    v.vh = v.vv = 30;
    return v;
}

PictureSettings every(int n) {
    PictureSettings p;
    p.xres = p.yres = n;
    p.jitter = 0, p.sampleSpacing = 1;
    return p;
}

}  // namespace

// A sphere lamp a tenth of a pixel wide, at 13 places across a pixel's centre: traced alone, the picture
// catches it whole or not at all; with sources drawn it collects L·π r²/D² each time (within 2%: the
// 16-gon outline's 1.3% more area, and the solid angle's variation across the pixels).
TEST(SmallSources, ASourceSmallerThanAPixelGivesItsLightWherever) {
    double r = 0.01, d = 10, radiance = 1000;
    double expected = radiance * M_PI * r * r / (d * d);
    PictureSettings p = every(32);  // a pixel spans ~0.95° here, the lamp 0.11°
    int caught = 0;
    for (int k = 0; k < 13; ++k) {
        double x = 0.07 + 0.0025 * k;  // across the centre of the pixel up and right of the axis, 0.48° off it
        TestScene t("void light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4 " + std::to_string(x) + " " +
                    std::to_string(d) + " 0.0837 " + std::to_string(r) + "\n");
        Sequence sequence(t.scene, t.render, fixedSeed());
        View v = lookingAt({0, 1, 0});
        p.drawSources = true;
        EXPECT_NEAR(collected(renderPicture(sequence, v, 0, p).picture, v), expected, 0.02 * expected) << k;
        p.drawSources = false;
        double alone = collected(renderPicture(sequence, v, 0, p).picture, v);
        EXPECT_TRUE(alone == 0 || alone > 20 * expected) << alone;  // all or nothing
        caught += alone > 0;
    }
    EXPECT_GT(caught, 0);
    EXPECT_LT(caught, 13);
}

// A square lamp, exactly outlined: its light within 0.5%, with pixels 5 or 18 times its width.
TEST(SmallSources, APolygonSourceIsDrawnByItsCoverage) {
    TestScene t("void light lamp 0 0 3 500 500 500\n"
                "lamp polygon tile 0 0 12 -0.013 8 -0.011 0.017 8 -0.011 0.017 8 0.019 -0.013 8 0.019\n");
    Sequence sequence(t.scene, t.render, fixedSeed());
    View v = lookingAt({0, 1, 0});
    double expected = 500 * 0.03 * 0.03 / 64 * std::pow(1 + (0.002 * 0.002 + 0.004 * 0.004) / 64, -1.5);
    EXPECT_NEAR(collected(renderPicture(sequence, v, 0, every(32)).picture, v), expected, 0.005 * expected);
    PictureSettings coarse = every(8);
    EXPECT_NEAR(collected(renderPicture(sequence, v, 0, coarse).picture, v), expected, 0.005 * expected);
}

// Something in front of the lamp hides it: nothing is drawn.
TEST(SmallSources, HiddenSourcesAreNotDrawn) {
    TestScene t("void light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4 0 10 0 0.01\n"
                "void plastic black 0 0 5 0 0 0 0 0\nblack polygon wall 0 0 12 -1 5 -1 1 5 -1 1 5 1 -1 5 1\n");
    Sequence sequence(t.scene, t.render, fixedSeed());
    View v = lookingAt({0, 1, 0});
    EXPECT_EQ(collected(renderPicture(sequence, v, 0, every(32)).picture, v), 0);
}

// A source wider than -ps pixels is left to the pixels' own rays.
TEST(SmallSources, WideSourcesAreLeftToThePixels) {
    TestScene t("void light lamp 0 0 3 50 50 50\nlamp polygon panel 0 0 12 -1 8 -1 1 8 -1 1 8 1 -1 8 1\n");
    Sequence sequence(t.scene, t.render, fixedSeed());
    View v = lookingAt({0, 1, 0});
    PictureSettings p = every(32);
    RenderedPicture drawn = renderPicture(sequence, v, 0, p);
    p.drawSources = false;
    EXPECT_EQ(drawn.picture.pixels, renderPicture(sequence, v, 0, p).picture.pixels);
}
