#include "sky/weather_tape.h"

#include <gtest/gtest.h>

#include <sstream>

namespace brume {
namespace {

const char* const kHeader =
    "LOCATION,Somewhere,ST,CTY,TMY3,123456,41.5,-87.5,-6.0,201.0\n"
    "DESIGN CONDITIONS,0\nTYPICAL/EXTREME PERIODS,0\nGROUND TEMPERATURES,0\nHOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\n"
    "COMMENTS 1,x\nCOMMENTS 2,y\nDATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31\n";

std::string epwRecord(int month, int day, int hour, const char* dew, const char* direct, const char* diffuse) {
    std::ostringstream r;
    r << "1999," << month << "," << day << "," << hour << ",0,?,-1.0," << dew << ",73,99500,0,0,218,0," << direct << "," << diffuse
      << ",0,0,0,0,270,2.6,9,9,24.1,2740,9,999999999,40,0.0000,0,88,999.000,999.0,99.0\n";
    return r.str();
}

TEST(WeatherTape, ReadsEpwRecordsAtTheMiddleOfTheirHour) {
    std::istringstream in(std::string(kHeader) + epwRecord(6, 21, 13, "11.5", "812", "97") + epwRecord(6, 21, 14, "99.9", "9999", "90"));
    WeatherTape tape(in, "x.epw");
    EXPECT_EQ(tape.units(), WeatherUnits::Epw);
    EXPECT_DOUBLE_EQ(tape.site().latitude, 41.5);
    EXPECT_DOUBLE_EQ(tape.site().longitude, -87.5);
    EXPECT_DOUBLE_EQ(tape.site().timeZone, -6);
    std::optional<WeatherRecord> a = tape.next(), b = tape.next();
    ASSERT_TRUE(a && b);
    EXPECT_DOUBLE_EQ(a->hour, 12.5);
    EXPECT_EQ(*a->dewPoint, 11.5);
    EXPECT_EQ(*a->direct, 812);
    EXPECT_EQ(*a->diffuse, 97);
    EXPECT_EQ(a->where.str(), "x.epw:9");
    EXPECT_FALSE(b->dewPoint);  // EPW's missing-value codes
    EXPECT_FALSE(b->direct);
    EXPECT_FALSE(tape.next());
}

TEST(WeatherTape, ReadsWeaHeadersWestPositive) {
    std::istringstream in("place A_B\nlatitude 45\nlongitude -8.000000\ntime_zone -15\nsite_elevation 250\nweather_data_file_units 2\n\n1 1 0.500 -0 0\n");
    WeatherTape tape(in, "x.wea");
    EXPECT_EQ(tape.units(), WeatherUnits::DirectHorizontalIrradiance);
    EXPECT_DOUBLE_EQ(tape.site().longitude, 8);
    EXPECT_DOUBLE_EQ(tape.site().timeZone, 1);
    EXPECT_EQ(tape.site().city, "A");
    std::optional<WeatherRecord> r = tape.next();  // past the blank line
    ASSERT_TRUE(r);
    EXPECT_EQ(r->where.str(), "x.wea:8");
}

TEST(WeatherTape, MalformedInputNamesTheLine) {
    struct Case {
        std::string text, message;
    };
    for (const Case& c : {Case{"nothing", "x:1: neither an EPW file"},
                          Case{"LOCATION,a,b,c\n", "x:1: LOCATION line with 4 fields, not 10"},
                          Case{"LOCATION,a,b,c,d,e,91,0,0,0\n", "x:1: latitude outside -90..90"},
                          Case{"LOCATION,a,b,c,d,e,41,-87,-6,201\nDESIGN CONDITIONS,0\nWRONG\n", "x:3: expected the EPW header's TYPICAL/EXTREME PERIODS line"},
                          Case{"LOCATION,a,b,c,d,e,41,-87,-6,201\n", "x:1: EPW header ends before its DESIGN CONDITIONS line"},
                          Case{std::string(kHeader) + "1999,6,21\n", "x:9: EPW record with 3 fields"},
                          Case{std::string(kHeader) + epwRecord(13, 1, 1, "1", "0", "0"), "x:9: impossible date or time"},
                          Case{std::string(kHeader) + epwRecord(6, 21, 13, "1", "lots", "0"), "x:9: bad direct normal irradiance 'lots'"}}) {
        std::istringstream in(c.text);
        try {
            WeatherTape tape(in, "x");
            while (tape.next()) {
            }
            ADD_FAILURE() << "accepted: " << c.message;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(c.message, 0), 0u) << e.what();
        }
    }
}

}  // namespace
}  // namespace brume
