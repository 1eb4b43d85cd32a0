#include "sky/sky_command.h"

#include <gtest/gtest.h>

#include "util/error.h"

using namespace brume;

TEST(SkyCommand, ClockTimesAsGenskyReadsThem) {
    EXPECT_DOUBLE_EQ(parseClockTime("14.5").hour, 14.5);
    EXPECT_DOUBLE_EQ(parseClockTime("14:30").hour, 14.5);
    EXPECT_DOUBLE_EQ(parseClockTime(".5").hour, 0.5);
    ClockTime solar = parseClockTime("+9:15");
    EXPECT_TRUE(solar.solar);
    EXPECT_DOUBLE_EQ(solar.hour, 9.25);
    EXPECT_FALSE(solar.meridian);
}

// A time zone sets the standard meridian (degrees west): EDT is 4 hours behind Greenwich, CEST 2 ahead.
TEST(SkyCommand, TimeZonesSetTheStandardMeridian) {
    ClockTime edt = parseClockTime("14:30EDT");
    EXPECT_DOUBLE_EQ(edt.hour, 14.5);
    EXPECT_DOUBLE_EQ(*edt.meridian, 60 * kDegree);
    EXPECT_DOUBLE_EQ(*parseClockTime("8cest").meridian, -30 * kDegree);
    EXPECT_DOUBLE_EQ(*parseClockTime("12NZST").meridian, -180 * kDegree);
}

TEST(SkyCommand, MalformedTimesAreRefused) {
    for (const char* bad : {"", "EST", "+12EST", "12.5.3", "12-3", "1 2"}) EXPECT_THROW(parseClockTime(bad), Error) << bad;
    EXPECT_THROW(parseClockTime("12XYZ"), Error);
}

TEST(SkyCommand, WhenIsADateAndTimeOrTheSunAngles) {
    SkyWhen date = parseWhen({"3", "21", "12EST"});
    EXPECT_FALSE(date.fromAngles);
    EXPECT_EQ(date.time.month, 3);
    EXPECT_EQ(date.time.day, 21);
    EXPECT_DOUBLE_EQ(*date.meridian, 75 * kDegree);
    SkyWhen angles = parseWhen({"-ang", "30", "-45"});
    EXPECT_TRUE(angles.fromAngles);
    EXPECT_DOUBLE_EQ(angles.angles.azimuth, -45 * kDegree);
    for (std::vector<std::string> bad : {std::vector<std::string>{"13", "1", "12"}, {"3", "0", "12"}, {"3", "21"}, {"x", "1", "2"}})
        EXPECT_THROW(parseWhen(bad), Error);
}
