#include "view/view.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

#include "util/error.h"

using namespace brume;

namespace {

constexpr double kDeg = M_PI / 180;

View parse(const std::string& text) {
    View v;
    parseViewString(v, text);
    return v;
}

void expectNear(const dvec3& a, const dvec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

dvec3 dirAt(const View& v, double x, double y) {
    auto r = v.ray(x, y);
    EXPECT_TRUE(r.has_value());
    return r ? r->dir : dvec3(0);
}

double angleBetween(const dvec3& a, const dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

}  // namespace

TEST(View, DefaultsAreRadiances) {
    View v;
    EXPECT_EQ(v.options(), "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0");
    EXPECT_EQ(v.problem(), "");
}

// Every view type looks along -vd at the centre of the image.
TEST(View, CentreLooksAlongViewDirection) {
    for (const char* type : {"-vtv", "-vtl", "-vth", "-vta", "-vts", "-vtc"}) {
        View v = parse(std::string(type) + " -vp 1 2 3 -vd 1 -2 .5 -vu 0 0 1 -vh 100 -vv 60");
        SCOPED_TRACE(type);
        expectNear(dirAt(v, .5, .5), glm::normalize(dvec3(1, -2, .5)));
        expectNear(v.ray(.5, .5)->org, {1, 2, 3});
    }
}

// A perspective image's corners lie at ±tan(vh/2), ±tan(vv/2) on the plane one unit ahead.
TEST(View, PerspectiveCornersAtTangentOfHalfAngles) {
    View v = parse("-vtv -vh 60 -vv 40");  // looking along +y, up +z, so right is +x
    double tx = std::tan(30 * kDeg), tz = std::tan(20 * kDeg);
    expectNear(dirAt(v, 1, 1), glm::normalize(dvec3(tx, 1, tz)));
    expectNear(dirAt(v, 0, 0), glm::normalize(dvec3(-tx, 1, -tz)));
    expectNear(dirAt(v, 1, 0), glm::normalize(dvec3(tx, 1, -tz)));
    expectNear(dirAt(v, .75, .5), glm::normalize(dvec3(tx / 2, 1, 0)));
    EXPECT_TRUE(std::isinf(v.ray(.3, .7)->tmax));
}

// A parallel view's rays all share -vd; their origins spread over vh by vv world units.
TEST(View, ParallelOriginsSpanTheViewSize) {
    View v = parse("-vtl -vp 1 2 3 -vh 4 -vv 2");
    for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 1.0}, {.25, .75}}) {
        auto r = v.ray(x, y);
        ASSERT_TRUE(r);
        expectNear(r->dir, {0, 1, 0});
        expectNear(r->org, dvec3(1 + 4 * (x - .5), 2, 3 + 2 * (y - .5)));
    }
}

// Hemispherical fisheye: the edge of a 180° image is 90° off axis, and the image radius goes as sin(angle).
TEST(View, HemisphericalEdgeIsNinetyDegrees) {
    View v = parse("-vth -vh 180 -vv 180");
    expectNear(dirAt(v, 1, .5), {1, 0, 0});
    expectNear(dirAt(v, .5, 0), {0, 0, -1});
    // half way to the edge: sin(angle) = 1/2
    EXPECT_NEAR(angleBetween(dirAt(v, .75, .5), {0, 1, 0}), 30 * kDeg, 1e-12);
    EXPECT_FALSE(v.ray(1, 1).has_value());  // outside the circle
    EXPECT_FALSE(v.ray(0, .01).has_value());
    // a narrower hemispherical view: its edge is vh/2 off axis
    EXPECT_NEAR(angleBetween(dirAt(parse("-vth -vh 120 -vv 120"), 1, .5), {0, 1, 0}), 60 * kDeg, 1e-12);
}

// Angular fisheye: the angle off axis grows linearly with image radius, vh/2 at the edge.
TEST(View, AngularEdgeIsHalfTheViewSize) {
    View v = parse("-vta -vh 180 -vv 180");
    expectNear(dirAt(v, 1, .5), {1, 0, 0});
    EXPECT_NEAR(angleBetween(dirAt(v, .75, .5), {0, 1, 0}), 45 * kDeg, 1e-12);
    EXPECT_NEAR(angleBetween(dirAt(v, .5, .9), {0, 1, 0}), 72 * kDeg, 1e-12);
    // As in Radiance, the corners outside the image circle still see, out to 180° off axis
    EXPECT_NEAR(angleBetween(dirAt(v, 1, 1), {0, 1, 0}), 180 * kDeg * std::sqrt(.5), 1e-12);
    View full = parse("-vta -vh 360 -vv 360");
    expectNear(dirAt(full, 1, .5), {0, -1, 0}, 1e-9);  // the edge of a 360° image looks backwards
    EXPECT_FALSE(full.ray(.95, .95).has_value());       // and beyond it there is nothing
    EXPECT_NEAR(angleBetween(dirAt(parse("-vta -vh 200 -vv 200"), 0, .5), {0, 1, 0}), 100 * kDeg, 1e-12);
}

// Planisphere (stereographic): image radius goes as tan(angle/2), vh/2 at the edge.
TEST(View, PlanisphereIsStereographic) {
    View v = parse("-vts -vh 180 -vv 180");
    expectNear(dirAt(v, 1, .5), {1, 0, 0});
    // half the edge radius: tan(a/2) = tan(45°)/2
    EXPECT_NEAR(angleBetween(dirAt(v, .5, .75), {0, 1, 0}), 2 * std::atan(.5), 1e-12);
    EXPECT_NEAR(angleBetween(dirAt(parse("-vts -vh 300 -vv 300"), 0, .5), {0, 1, 0}), 150 * kDeg, 1e-12);
    // corners are beyond vh/2 but still give rays
    EXPECT_TRUE(v.ray(1, 1).has_value());
}

// Cylindrical panorama: horizontal angle linear across the image, perspective (tangent) vertically.
TEST(View, CylindricalIsAngularAcrossPerspectiveUp) {
    View v = parse("-vtc -vh 360 -vv 90");
    expectNear(dirAt(v, .75, .5), {1, 0, 0});
    expectNear(dirAt(v, 0, .5), {0, -1, 0});  // both edges of a 360° panorama look backwards
    expectNear(dirAt(v, 1, .5), {0, -1, 0});
    expectNear(dirAt(v, .5, 1), glm::normalize(dvec3(0, 1, 1)));  // tan(45°) = 1 at the top
    double a = 60 * kDeg, up = 2 * std::tan(45 * kDeg) * .3;     // x = .5 + 60/360, y = .8
    expectNear(dirAt(v, .5 + 60. / 360, .8), glm::normalize(dvec3(std::sin(a), std::cos(a), up)));
}

// -vs and -vl shift the image by whole widths and heights: -vs 1 puts x = 0 where x = 1 was.
TEST(View, ShiftAndLiftMoveTheImage) {
    View plain = parse("-vtv -vh 60 -vv 40");
    View shifted = parse("-vtv -vh 60 -vv 40 -vs .5 -vl -.25");
    expectNear(dirAt(shifted, .5, .5), dirAt(plain, 1, .25));
    expectNear(dirAt(shifted, .2, .9), dirAt(plain, .7, .65));
    View hem = parse("-vth -vh 180 -vv 180 -vs .5");
    EXPECT_FALSE(hem.ray(.9, .5).has_value());
    expectNear(dirAt(hem, .5, .5), {1, 0, 0});
}

// -vo moves the origin forward to the fore plane; -va limits the ray at the aft plane. In a perspective view
// these are planes perpendicular to -vd, so corner rays start and end further away.
TEST(View, ForeAndAftClippingPlanes) {
    View v = parse("-vtv -vh 90 -vv 90 -vo 2 -va 5");
    auto c = v.ray(.5, .5);
    expectNear(c->org, {0, 2, 0});
    EXPECT_NEAR(c->tmax, 3, 1e-12);
    auto corner = v.ray(1, 1);  // direction (1, 1, 1) before normalising
    expectNear(corner->org, {2, 2, 2});
    EXPECT_NEAR(corner->tmax, 3 * std::sqrt(3.), 1e-12);
    expectNear(corner->org + corner->tmax * corner->dir, {5, 5, 5});
    // parallel: plain distances along -vd
    auto p = parse("-vtl -vh 2 -vv 2 -vo 1 -va 4").ray(0, 0);
    expectNear(p->org, {-1, 1, -1});
    EXPECT_NEAR(p->tmax, 3, 1e-12);
    // fisheye: spheres about the view point
    auto h = parse("-vth -vh 180 -vv 180 -vo 1 -va 4").ray(1, .5);
    expectNear(h->org, {1, 0, 0});
    EXPECT_NEAR(h->tmax, 3, 1e-12);
}

TEST(View, ParsesArgumentListAndCountsWhatItUsed) {
    std::vector<std::string> args{"-vtc", "-vp", "1", "2", "3", "-vh", "90", "-vf", "x.vf", "-ab", "2"};
    View v;
    std::span<const std::string> rest(args);
    EXPECT_EQ(parseViewOption(v, rest), 1u);
    EXPECT_EQ(parseViewOption(v, rest.subspan(1)), 4u);
    EXPECT_EQ(parseViewOption(v, rest.subspan(5)), 2u);
    EXPECT_EQ(parseViewOption(v, rest.subspan(7)), 0u);  // -vf is the caller's
    EXPECT_EQ(parseViewOption(v, rest.subspan(9)), 0u);
    EXPECT_EQ(v.type, kCylindrical);
    EXPECT_EQ(v.vp, dvec3(1, 2, 3));
    EXPECT_EQ(v.vh, 90);
}

TEST(View, MalformedOptionValuesAreErrors) {
    View v;
    std::vector<std::string> shortVp{"-vp", "1", "2"}, badVh{"-vh", "wide"};
    EXPECT_THROW(parseViewOption(v, shortVp), Error);
    try {
        parseViewOption(v, badVh);
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "-vh needs a number");
    }
}

// A VIEW= header line and a view file's program line both parse; other words are skipped.
TEST(View, ParsesViewStrings) {
    View v;
    EXPECT_EQ(parseViewString(v, "VIEW= -vta -vp 1 2 3 -vd 0 0 -1 -vu 0 1 0 -vh 180 -vv 180"), 6);
    EXPECT_EQ(v.type, kAngular);
    EXPECT_EQ(v.vd, dvec3(0, 0, -1));
    View w;
    EXPECT_EQ(parseViewString(w, "rvu -vtl -vh 10 -vv 5 -x 512 -vs .5 -vl bad -vo 2\n"), 5);
    EXPECT_EQ(w.type, kParallel);
    EXPECT_EQ(w.vh, 10);
    EXPECT_EQ(w.vs, .5);
    EXPECT_EQ(w.vl, 0);
    EXPECT_EQ(w.vo, 2);
    EXPECT_TRUE(isViewLine("VIEW= -vtv"));
    EXPECT_TRUE(isViewLine("/usr/local/bin/rpict -vtv -vp 0 0 0"));
    EXPECT_TRUE(isViewLine("rvu -vth"));
    EXPECT_FALSE(isViewLine("EXPOSURE=1"));
    EXPECT_FALSE(isViewLine("rtrace -ab 2"));
}

TEST(View, PrintedOptionsReadBackToTheSameView) {
    for (const char* text :
         {"-vtv -vp 1.5 -2 3.25 -vd 1 1 0 -vu 0 0 1 -vh 60 -vv 40 -vo 0 -va 0 -vs 0 -vl 0",
          "-vth -vp 0 0 1.7 -vd 0 0 2 -vu 0 1 0 -vh 180 -vv 180 -vo .5 -va 100 -vs -.25 -vl .125",
          "-vtl -vp 10 20 30 -vd 0 -1 0 -vu 0 0 1 -vh 12.5 -vv 8 -vo 0 -va 0 -vs 0 -vl 0",
          "-vta -vp 0 0 0 -vd 1 0 0 -vu 0 0 1 -vh 360 -vv 360 -vo 0 -va 0 -vs 0 -vl 0",
          "-vts -vp 0 0 0 -vd 1 0 0 -vu 0 0 1 -vh 200 -vv 180 -vo 0 -va 0 -vs 0 -vl 0",
          "-vtc -vp 0 0 0 -vd 1 0 0 -vu 0 0 1 -vh 300 -vv 100 -vo 0 -va 0 -vs 0 -vl 0"}) {
        View v = parse(text);
        View back = parse(v.options());
        EXPECT_EQ(back, v) << text;
        EXPECT_EQ(back.options(), v.options());
    }
    // the direction's length is kept, as Radiance's VIEW= lines keep it
    EXPECT_EQ(parse("-vd 0 0 2").options().find("-vd 0 0 2 "), 15u);
    EXPECT_EQ(parse("-vtv -vp 0.1234567891 0 0").options().substr(0, 22), "-vtv -vp 0.1234568 0 0");
}

TEST(View, BadViewsGiveRadiancesMessages) {
    EXPECT_EQ(parse("-vd 0 0 0").problem(), "zero view direction");
    EXPECT_EQ(parse("-vu 0 0 0").problem(), "zero view up vector");
    EXPECT_EQ(parse("-vd 0 0 1 -vu 0 0 1").problem(), "view up parallel to view direction");
    EXPECT_EQ(parse("-vd 0 0 -3 -vu 0 0 1").problem(), "view up parallel to view direction");
    EXPECT_EQ(parse("-vh 0").problem(), "illegal horizontal view size");
    EXPECT_EQ(parse("-vv -5").problem(), "illegal vertical view size");
    EXPECT_EQ(parse("-vtv -vh 180").problem(), "illegal horizontal view size");
    EXPECT_EQ(parse("-vth -vv 181").problem(), "illegal vertical view size");
    EXPECT_EQ(parse("-vta -vh 361").problem(), "illegal horizontal view size");
    EXPECT_EQ(parse("-vts -vh 360").problem(), "illegal horizontal view size");
    EXPECT_EQ(parse("-vtc -vh 360 -vv 180").problem(), "illegal vertical view size");
    EXPECT_EQ(parse("-vtl -vh 1000 -vv 1000").problem(), "");
    EXPECT_EQ(parse("-vo 2 -va 1").problem(), "illegal fore/aft clipping plane");
    EXPECT_EQ(parse("-vo -1").problem(), "illegal fore/aft clipping plane");
    EXPECT_EQ(parse("-vtx").problem(), "unknown view type");
    EXPECT_EQ(parse("-vtp").problem(), "unknown view type");  // Radiance has no -vtp
    EXPECT_FALSE(parse("-vd 0 0 0").ray(.5, .5).has_value());
    try {
        parse("-vd 0 0 1 -vu 0 0 1").validate();
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "view up parallel to view direction");
    }
    EXPECT_NO_THROW(View().validate());
}

// Rays printed by Radiance 6.1's own vwrays (`vwrays -fa -pa 0 -x 4 -y 4 <view>`, lines 1, 7 and 16: pixel
// centres (.125, .875), (.625, .625), (.875, .125)). vwrays prints a zero direction outside a fisheye's
// circle, and the direction scaled by the clip length when -va is set.
TEST(View, MatchesRadiancesVwrays) {
    struct Case {
        const char* view;
        dvec3 org[3], dir[3];
    };
    const Case cases[] = {
        {"-vtv -vh 60 -vv 40 -vd 1 2 .5 -vu 0 0 1",
         {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
         {{2.00264e-02, 9.01945e-01, 4.31386e-01},
          {5.48725e-01, 7.79299e-01, 3.02644e-01},
          {7.56968e-01, 6.52043e-01, -4.28888e-02}}},
        {"-vtl -vh 4 -vv 2 -vp 1 2 3 -vd 0 0 -1 -vu 0 1 0",
         {{-5.00000e-01, 2.75000e+00, 3}, {1.5, 2.25, 3}, {2.5, 1.25, 3}},
         {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}},
        {"-vth -vh 180 -vv 150", {}, {{0, 0, 0}, {2.50000e-01, 9.37650e-01, 2.41481e-01}, {0, 0, 0}}},
        {"-vta -vh 270 -vv 200 -vs .1",
         {},
         {{-6.77835e-01, -2.67861e-01, 6.84682e-01},
          {8.42780e-01, 4.11627e-01, 3.46823e-01},
          {4.50136e-01, -8.53278e-01, -2.63237e-01}}},
        {"-vts -vh 200 -vv 180 -vl .2",
         {},
         {{-5.72700e-01, -3.59263e-01, 7.36848e-01},
          {3.94289e-01, 3.23393e-01, 8.60205e-01},
          {9.30376e-01, 4.09046e-02, -3.64317e-01}}},
        {"-vtc -vh 300 -vv 100 -vd 1 0 0",
         {},
         {{-2.85322e-01, 6.88829e-01, 6.66413e-01},
          {7.60325e-01, -5.83418e-01, 2.85535e-01},
          {-2.85322e-01, -6.88829e-01, -6.66413e-01}}},
        {"-vtv -vp 1 2 3 -vd 1 1 0 -vh 50 -vv 30 -vs .25 -vl -.5 -vo 1 -va 10",
         {{1.62467e+00, 2.78954e+00, 2.93301e+00},
          {1.95440e+00, 2.45981e+00, 2.79904e+00},
          {2.11927e+00, 2.29495e+00, 2.53109e+00}},
         {{5.62207e+00, 7.10585e+00, -6.02886e-01},
          {8.58963e+00, 4.13829e+00, -1.80866e+00},
          {1.00734e+01, 2.65451e+00, -4.22020e+00}}},
    };
    const double xs[] = {.125, .625, .875}, ys[] = {.875, .625, .125};
    for (const Case& c : cases) {
        View v = parse(c.view);
        ASSERT_EQ(v.problem(), "") << c.view;
        for (int i = 0; i < 3; i++) {
            SCOPED_TRACE(std::string(c.view) + " point " + std::to_string(i));
            auto r = v.ray(xs[i], ys[i]);
            if (c.dir[i] == dvec3(0)) {
                EXPECT_FALSE(r.has_value());
                continue;
            }
            ASSERT_TRUE(r.has_value());
            dvec3 d = std::isinf(r->tmax) ? r->dir : r->dir * r->tmax;
            double scale = std::max(1.0, glm::length(c.dir[i]));
            expectNear(r->org, c.org[i], 1e-5 * std::max(1.0, glm::length(c.org[i])));
            expectNear(d, c.dir[i], 1e-5 * scale);
        }
    }
}

// location() undoes ray(): the point a pixel's ray reaches, 3 units on, projects back onto that pixel, for
// every view type, shifted and lifted too; points behind are refused.
TEST(View, LocationIsTheInverseOfRay) {
    for (char type : {'v', 'l', 'h', 'a', 's', 'c'}) {
        View v;
        v.type = type;
        v.vp = {1, 2, 3};
        v.vd = {0.3, 1, -0.2};
        v.vh = type == 'l' ? 4 : type == 'v' ? 60 : 150;
        v.vv = type == 'l' ? 3 : type == 'v' ? 45 : 120;
        v.vs = 0.1, v.vl = -0.05;
        for (double x : {0.02, 0.3, 0.5, 0.91})
            for (double y : {0.07, 0.5, 0.8}) {
                auto r = v.ray(x, y);
                if (!r) continue;
                auto at = v.location(r->org + 3.0 * r->dir);
                ASSERT_TRUE(at) << type;
                EXPECT_NEAR(at->x, x, 1e-9) << type << " " << x << " " << y;
                EXPECT_NEAR(at->y, y, 1e-9) << type << " " << x << " " << y;
            }
    }
    View v;
    EXPECT_FALSE(v.location({0, -1, 0}));  // behind a perspective view
}
