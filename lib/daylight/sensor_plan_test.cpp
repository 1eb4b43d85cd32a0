#include "daylight/sensor_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace brume {
namespace {

// A 3 × 2 grid, 0.5 m apart: eight pixels a spacing, each sensor's value over its square cell, the plan's
// corners in the corner sensors' cells.
TEST(SensorPlan, DrawsARegularGridCellByCell) {
    std::vector<dvec3> grid;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) grid.push_back(dvec3(1 + 0.5 * i, 2 + 0.5 * j, 0.8));
    SensorPlan plan(grid);
    EXPECT_DOUBLE_EQ(plan.spacing(), 0.5);
    ASSERT_EQ(plan.width(), 24);
    ASSERT_EQ(plan.height(), 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) EXPECT_EQ(plan.sensorAt(x, y), x / 8 + 3 * (1 - y / 8)) << x << " " << y;
    Picture p = plan.map({0, 10, 20, 30, 40, -5}, {"a line"});
    EXPECT_EQ(p.at(4, 12)[0], 0.f);     // sensor 0: the lowest row, the smallest x
    EXPECT_EQ(p.at(12, 12)[1], 10.f);   // sensor 1
    EXPECT_EQ(p.at(20, 4)[2], 0.f);     // sensor 5: negative shown as 0
    EXPECT_EQ(p.at(4, 4)[0], 30.f);     // sensor 3: the top row
    ASSERT_EQ(p.header.size(), 2u);
    EXPECT_EQ(p.header[0], "a line");
    EXPECT_EQ(p.header[1], "VIEW= -vtl -vp 1.5 2.25 0.8 -vd 0 0 -1 -vu 0 1 0 -vh 1.5 -vv 1");
    EXPECT_THROW(plan.map({1, 2}, {}), Error);
}

// A grid rotated by 30° with a corner missing (an L-shaped room): every pixel shows the sensor nearest to its
// centre when one is within 0.75 spacing, none otherwise (the plan starts at the sensors' smallest x and y,
// half a spacing out); each sensor's cell is about a spacing square.
TEST(SensorPlan, DrawsAnyLayoutByNearestSensor) {
    const double step = 0.6, c = std::cos(0.5236), s = std::sin(0.5236);
    std::vector<dvec3> sensors;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 8; ++i)
            if (i < 4 || j < 3) sensors.push_back(dvec3(100 + step * (c * i - s * j), -50 + step * (s * i + c * j), 3));
    SensorPlan plan(sensors);
    EXPECT_NEAR(plan.spacing(), step, 1e-9);
    const double pixel = step / 8;
    double lowX = 1e9, lowY = 1e9;
    for (const dvec3& p : sensors) lowX = std::min(lowX, p.x), lowY = std::min(lowY, p.y);
    std::vector<int> owned(sensors.size(), 0);
    for (int y = 0; y < plan.height(); ++y)
        for (int x = 0; x < plan.width(); ++x) {
            double px = lowX - step / 2 + (x + 0.5) * pixel, py = lowY - step / 2 + (plan.height() - y - 0.5) * pixel;
            int nearest = -1;
            double best = 0.75 * step;
            for (size_t k = 0; k < sensors.size(); ++k) {
                double d = std::hypot(sensors[k].x - px, sensors[k].y - py);
                if (d < best) best = d, nearest = int(k);
            }
            ASSERT_EQ(plan.sensorAt(x, y), nearest) << x << " " << y;
            if (nearest >= 0) ++owned[nearest];
        }
    for (size_t k = 0; k < sensors.size(); ++k) {
        EXPECT_GT(owned[k], 50) << k;  // 64 for a whole cell, less at the border's cut corners
        EXPECT_LT(owned[k], 100) << k;
    }
}

TEST(SensorPlan, RefusesSensorsSharingXAndYAndEmptyGrids) {
    EXPECT_THROW(SensorPlan(std::vector<dvec3>{}), Error);
    try {
        SensorPlan({dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 0, 3)});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "sensors 0 and 2 share x and y (a grid on two storeys?): one plan a storey");
    }
    SensorPlan one({dvec3(5, 5, 1)});
    EXPECT_EQ(one.spacing(), 1);
    EXPECT_EQ(one.sensorAt(4, 4), 0);
}

// Far-apart groups: the picture stays within 2048 pixels a side.
TEST(SensorPlan, StaysAPictureOneCanOpen) {
    std::vector<dvec3> sensors;
    for (int i = 0; i < 4; ++i) sensors.push_back(dvec3(0.1 * i, 0, 0)), sensors.push_back(dvec3(5000 + 0.1 * i, 0, 0));
    SensorPlan plan(sensors);
    EXPECT_LE(plan.width(), 2048);
    EXPECT_GE(plan.width(), 2047);
}

}  // namespace
}  // namespace brume
