#include "daylight/annual_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "util/error.h"

namespace brume {
namespace {

// Honeybee-radiance-postprocess's own functions (5190635d, run on this case with numpy): one sensor over eight
// occupied hours with results and two occupied hours without (the sun down): DA 40, cDA 56.67, UDI 50,
// UDI-lower 40, UDI-upper 10 — the thresholds' edges counted as Honeybee counts them.
TEST(AnnualMetrics, AgreeWithHoneybeesOnAHandMadeSensor) {
    HourlyIlluminance e;
    e.sensors = 1;
    e.lux = {0, 150, 299.99f, 300, 600, 3000, 3000.5f, 50, 5000};
    e.hours = {8, 9, 10, 11, 12, 13, 14, 15, 16};
    std::vector<bool> occupied(kHoursInYear);
    for (int h : {8, 9, 10, 11, 12, 13, 14, 15, 20, 21}) occupied[h] = true;  // not 16: its 5000 lx do not count
    SensorMetrics m = annualMetrics(e, occupied, {})[0];
    EXPECT_NEAR(m.da, 40, 1e-9);
    EXPECT_NEAR(m.cda, 56.6663, 1e-3);
    EXPECT_NEAR(m.udi, 50, 1e-9);
    EXPECT_NEAR(m.udiLower, 40, 1e-9);
    EXPECT_NEAR(m.udiUpper, 10, 1e-9);
    EXPECT_NEAR(m.udiLower + m.udi + m.udiUpper, 100, 1e-9);
    EXPECT_EQ(hoursAbove(e, occupied, 1000), (std::vector<int>{2}));
    EXPECT_THROW(annualMetrics(e, std::vector<bool>(kHoursInYear), {}), Error);
    EXPECT_THROW(annualMetrics(e, std::vector<bool>(24), {}), Error);
}

TEST(AnnualMetrics, DefaultScheduleIsEightToSixEveryDay) {
    std::vector<bool> o = eightToSix();
    EXPECT_EQ(std::count(o.begin(), o.end(), true), 3650);
    EXPECT_FALSE(o[7]);
    EXPECT_TRUE(o[8]);
    EXPECT_TRUE(o[17]);
    EXPECT_FALSE(o[18]);
}

TEST(AnnualMetrics, SpatialSharesOfSensors) {
    std::vector<SensorMetrics> m(4);
    m[0].da = 50, m[1].da = 49.99, m[2].da = 80, m[3].da = 0;
    EXPECT_DOUBLE_EQ(spatialDaylightAutonomy(m), 50);
    EXPECT_DOUBLE_EQ(annualSunlightExposure({250, 249, 0, 1000}), 50);
}

// The brightest half of the year, ties to the earlier hour: a day of 24 hours where the 12 brightest are
// the daylight hours, and a dark year where the first 4380 hours are.
TEST(AnnualMetrics, DaylightHoursAreTheBrightestHalfOfTheYear) {
    std::vector<double> diffuse(kHoursInYear);
    for (int h = 0; h < kHoursInYear; ++h) diffuse[h] = h % 24 >= 6 && h % 24 < 18 ? 100 + h % 24 : 0;
    std::vector<bool> d = daylightHours(diffuse);
    EXPECT_EQ(std::count(d.begin(), d.end(), true), 4380);
    for (int h = 0; h < 48; ++h) EXPECT_EQ(d[h], h % 24 >= 6 && h % 24 < 18) << h;
    std::vector<bool> dark = daylightHours(std::vector<double>(kHoursInYear));
    EXPECT_TRUE(dark[4379]);
    EXPECT_FALSE(dark[4380]);
    EXPECT_THROW(daylightHours(std::vector<double>(10)), Error);
}

// EN 17037's levels: sensors at 400 lx through the daylight hours meet the target at 300 (the minimum level)
// and the minimum illuminance at 100 and 300 (the medium level); with a tenth of them dark, the minimum
// criterion's 95 % fails at every level.
TEST(AnnualMetrics, En17037LevelsByEachCriterion) {
    std::vector<bool> daylight(kHoursInYear);
    HourlyIlluminance e;
    e.sensors = 10;
    for (int h = 0; h < kHoursInYear; ++h) daylight[h] = h % 2 == 0;
    for (int h = 0; h < kHoursInYear; h += 2) e.hours.push_back(h);
    e.lux.assign(size_t(e.sensors) * e.hours.size(), 400);
    En17037 r = en17037(e, daylight);
    EXPECT_EQ(r.targetLevel, 1);
    EXPECT_EQ(r.minimumLevel, 2);
    EXPECT_EQ(r.level, 1);
    EXPECT_DOUBLE_EQ(r.targetShare[1], 0);
    std::fill(e.lux.begin(), e.lux.begin() + e.hours.size(), 0.f);
    r = en17037(e, daylight);
    EXPECT_DOUBLE_EQ(r.minimumShare[0], 90);
    EXPECT_EQ(r.minimumLevel, 0);
    EXPECT_EQ(r.level, 0);
    EXPECT_EQ(r.targetLevel, 1);
}

}  // namespace
}  // namespace brume
