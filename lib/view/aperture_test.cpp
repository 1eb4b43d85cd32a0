#include "view/aperture.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sampling/random.h"

using namespace brume;

namespace {

View parse(const std::string& text) {
    View v;
    parseViewString(v, text);
    return v;
}

// The distance from point p to the line through a along unit d.
double distanceToLine(const dvec3& p, const dvec3& a, const dvec3& d) {
    dvec3 w = p - a;
    return glm::length(w - glm::dot(w, d) * d);
}

}  // namespace

// A perspective lens focused at 4 (|-vd|): every ray through a pixel meets the pinhole ray of that pixel on
// the focal plane, and starts on the aperture disc around the view point, in the image plane.
TEST(ViewAperture, PerspectiveRaysMeetOnTheFocalPlane) {
    View v = parse("-vtv -vp 1 2 3 -vd 0 4 0 -vh 60 -vv 40");
    Random random(7);
    for (int i = 0; i < 200; ++i) {
        double x = random.uniform(), y = random.uniform();
        ViewRay pinhole = *v.ray(x, y), r = pinhole;
        ASSERT_TRUE(jitterAperture(v, r, .5, random.uniform(), random.uniform(), random.uniform()));
        dvec3 focal = pinhole.org + 4 / pinhole.dir.y * pinhole.dir;  // on the plane y = 2 + 4
        EXPECT_LT(distanceToLine(focal, r.org, r.dir), 1e-12);
        EXPECT_NEAR(r.org.y, 2, 1e-12);
        EXPECT_LE(glm::length(r.org - v.vp), .25 + 1e-12);
        EXPECT_NEAR(glm::length(r.dir), 1, 1e-12);
        EXPECT_EQ(r.tmax, pinhole.tmax);
    }
}

// The concentric map covers the whole disc: the aperture's rim is reached.
TEST(ViewAperture, OriginsFillTheDisc) {
    View v = parse("-vtv -vd 0 2 0");
    ViewRay r = *v.ray(.5, .5);
    ASSERT_TRUE(jitterAperture(v, r, 1, 1, .5, 0));
    EXPECT_NEAR(glm::length(r.org), .5, 1e-6);
    r = *v.ray(.5, .5);
    ASSERT_TRUE(jitterAperture(v, r, 1, .5, .5, 0));
    EXPECT_NEAR(glm::length(r.org), 0, 1e-12);
}

// -vo moves the jittered origin forward onto the fore plane again.
TEST(ViewAperture, ForeClippingPlaneIsKept) {
    View v = parse("-vtv -vd 0 3 0 -vo 1 -vh 50 -vv 50");
    ViewRay r = *v.ray(.9, .2);
    ASSERT_TRUE(jitterAperture(v, r, .4, .1, .8, .5));
    EXPECT_NEAR(r.org.y, 1, 1e-12);
}

// A parallel view keeps each pixel's place: its rays start around the pixel and meet at its focal point.
TEST(ViewAperture, ParallelPixelsKeepTheirPlace) {
    View v = parse("-vtl -vp 0 0 0 -vd 0 5 0 -vh 4 -vv 2");
    ViewRay pinhole = *v.ray(1, 1), r = pinhole;  // origin (2, 0, 1)
    ASSERT_TRUE(jitterAperture(v, r, .2, .3, .9, .5));
    EXPECT_LE(glm::length(r.org - pinhole.org), .1 + 1e-12);
    EXPECT_LT(distanceToLine(dvec3(2, 5, 1), r.org, r.dir), 1e-12);
}

// Fisheyes focus on a sphere about the view point; their lens also moves along -vd, by at most π/8 of
// the diameter either way.
TEST(ViewAperture, FisheyeRaysMeetOnTheFocalSphere) {
    View v = parse("-vth -vp 0 0 0 -vd 0 0 -2 -vu 0 1 0 -vh 180 -vv 180");
    Random random(3);
    for (int i = 0; i < 100; ++i) {
        auto pinhole = v.ray(.2 + .6 * random.uniform(), .2 + .6 * random.uniform());
        ASSERT_TRUE(pinhole);
        ViewRay r = *pinhole;
        ASSERT_TRUE(jitterAperture(v, r, .3, random.uniform(), random.uniform(), random.uniform()));
        EXPECT_LT(distanceToLine(2.0 * pinhole->dir, r.org, r.dir), 1e-12);
        EXPECT_LE(std::abs(r.org.z), M_PI / 8 * .3 + 1e-12);
        EXPECT_LE(std::hypot(r.org.x, r.org.y), .15 + 1e-12);
    }
}

TEST(ViewAperture, TinyDiameterChangesNothing) {
    View v = parse("-vtv -vd 0 2 0");
    ViewRay r = *v.ray(.3, .6), before = r;
    ASSERT_TRUE(jitterAperture(v, r, 1e-7, .9, .9, .9));
    EXPECT_EQ(r.org, before.org);
    EXPECT_EQ(r.dir, before.dir);
}
