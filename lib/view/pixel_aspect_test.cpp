#include "view/pixel_aspect.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"
#include "view/view.h"

using namespace brume;

namespace {

constexpr double kDeg = M_PI / 180;

View parse(const std::string& text) {
    View v;
    parseViewString(v, text);
    return v;
}

// The resolution Radiance 6.1's `vwrays -d <view> -x X -y Y -pa P` prints.
std::pair<int, int> fitted(const std::string& view, int x, int y, double pa = 1) {
    normalizeResolution(parse(view).aspect(), pa, x, y);
    return {x, y};
}

}  // namespace

// Each view type's image is as tall, relative to its width, as its projection of vv against vh.
TEST(ViewAspect, IsTheImageHeightOverWidth) {
    EXPECT_NEAR(parse("-vtv -vh 60 -vv 40").aspect(), std::tan(20 * kDeg) / std::tan(30 * kDeg), 1e-12);
    EXPECT_NEAR(parse("-vtl -vh 3 -vv 2").aspect(), 2. / 3, 1e-12);
    EXPECT_NEAR(parse("-vta -vh 360 -vv 180").aspect(), .5, 1e-12);
    EXPECT_NEAR(parse("-vth -vh 180 -vv 120").aspect(), std::sin(60 * kDeg), 1e-12);
    EXPECT_NEAR(parse("-vts -vh 200 -vv 150").aspect(), std::tan(37.5 * kDeg) / std::tan(50 * kDeg), 1e-12);
    EXPECT_NEAR(parse("-vtc -vh 360 -vv 90").aspect(), 2 / (2 * M_PI), 1e-12);
    EXPECT_THROW(parse("-vtv -vh 180").aspect(), Error);
}

// Figures printed by Radiance 6.1's vwrays -d for the same views and resolutions.
TEST(ViewAspect, NormalizeResolutionMatchesRadiance) {
    EXPECT_EQ(fitted("-vh 90 -vv 45", 16, 8, .5), std::pair(10, 8));
    EXPECT_EQ(fitted("-vtv -vh 40 -vv 60", 100, 100), std::pair(63, 100));
    EXPECT_EQ(fitted("-vtc -vh 360 -vv 90", 1000, 1000), std::pair(1000, 318));
    EXPECT_EQ(fitted("-vth -vh 180 -vv 120", 100, 100), std::pair(100, 87));
    EXPECT_EQ(fitted("-vta -vh 360 -vv 180", 512, 512), std::pair(512, 256));
    EXPECT_EQ(fitted("-vts -vh 200 -vv 150", 400, 400), std::pair(400, 258));
    EXPECT_EQ(fitted("-vtl -vh 3 -vv 2", 7, 7), std::pair(7, 5));
    EXPECT_EQ(fitted("-vtl -vh 3 -vv 2", 7, 7, 1.5), std::pair(7, 3));
    // halves round up: 3.5 pixels become 4, in x and in y
    EXPECT_EQ(fitted("-vtl -vh 2 -vv 3", 7, 7, .75), std::pair(4, 7));
    EXPECT_EQ(fitted("-vtv -vh 45 -vv 45", 7, 7, 2), std::pair(7, 4));
}

// -pa 0 keeps the resolution and reports the pixel shape it implies.
TEST(ViewAspect, ZeroPixelAspectKeepsResolution) {
    double pa = 0;
    int x = 9, y = 8;
    normalizeResolution(1, pa, x, y);
    EXPECT_EQ(x, 9);
    EXPECT_EQ(y, 8);
    EXPECT_DOUBLE_EQ(pa, 1.125);
}
