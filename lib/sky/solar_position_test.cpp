#include "sky/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

using namespace brume;

namespace {

// Reda & Andreas (2004), "Solar position algorithm for solar radiation applications", NREL/TP-560-34302,
// worked example: Golden, Colorado (39.742476° N, 105.1786° W, MST on 105° W), 2003-10-17 12:30:30.
// Their topocentric elevation without refraction 39.872046°, azimuth 194.340241° east of north.
const Site kGolden{39.742476 * kDegree, 105.1786 * kDegree, 105 * kDegree};
const double kSpaAltitude = 39.872046, kSpaAzimuthWestOfSouth = 194.340241 - 180;

SunAngles sunAt(const LocalTime& t, const Site& site) {
    SunDeclination d = sunDeclination(t, site);
    return sunAngles(d.declination, d.solarTime, site);
}

}  // namespace

// With a year, Michalsky's almanac algorithm is good to 0.01° (Michalsky 1988) against NREL's SPA.
TEST(SolarPosition, MichalskyAlmanacMatchesNrelSpaWithinHundredthDegree) {
    SunAngles sun = sunAt({2003, 10, 17, 12 + 30 / 60.0 + 30 / 3600.0, false}, kGolden);
    EXPECT_NEAR(sun.altitude / kDegree, kSpaAltitude, 0.01);
    EXPECT_NEAR(sun.azimuth / kDegree, kSpaAzimuthWestOfSouth, 0.01);
}

// Without a year the IES sine fit of the declination is off by up to about a degree (here in October),
// which is what Radiance's gensky gives too.
TEST(SolarPosition, IesFormulasAreWithinAboutADegree) {
    SunAngles sun = sunAt({0, 10, 17, 12 + 30 / 60.0 + 30 / 3600.0, false}, kGolden);
    EXPECT_NEAR(sun.altitude / kDegree, kSpaAltitude, 1.1);
    EXPECT_NEAR(sun.azimuth / kDegree, kSpaAzimuthWestOfSouth, 0.5);
}

// The equation of time at its extremes (NOAA, Astronomical Almanac): sundials are 14.2 min slow on
// February 11 and 16.4 min fast on November 3; on the standard meridian that is the whole correction.
TEST(SolarPosition, SolarTimeFollowsTheEquationOfTime) {
    Site onMeridian{0.66, 75 * kDegree, 75 * kDegree};
    EXPECT_NEAR((sunDeclination({0, 2, 11, 12, false}, onMeridian).solarTime - 12) * 60, -14.2, 0.3);
    EXPECT_NEAR((sunDeclination({0, 11, 3, 12, false}, onMeridian).solarTime - 12) * 60, 16.4, 0.3);
    // Four minutes of solar time per degree of longitude west of the meridian.
    Site west{0.66, 76 * kDegree, 75 * kDegree};
    EXPECT_NEAR((sunDeclination({0, 4, 15, 12, false}, west).solarTime -
                 sunDeclination({0, 4, 15, 12, false}, onMeridian).solarTime) * 60, -4, 1e-9);
    EXPECT_EQ(sunDeclination({0, 4, 15, 9.5, true}, west).solarTime, 9.5);  // solar time given: kept
}

TEST(SolarPosition, DeclinationSpansTheTropics) {
    EXPECT_NEAR(iesDeclination(dayOfYear(6, 21)) / kDegree, 23.44, 0.05);
    EXPECT_NEAR(iesDeclination(dayOfYear(12, 21)) / kDegree, -23.44, 0.05);
    EXPECT_NEAR(iesDeclination(dayOfYear(3, 20)) / kDegree, 0, 1);  // the IES fit is a day late here
}

// At solar noon the sun is due south at 90° - latitude + declination; in the morning it is in the east,
// which is +x in the scene and a negative azimuth (azimuth is west of south).
TEST(SolarPosition, NoonSunIsDueSouthAndMorningSunInTheEast) {
    Site site{45 * kDegree, 0, 0};
    double declination = iesDeclination(dayOfYear(6, 21));
    SunAngles noon = sunAngles(declination, 12, site);
    EXPECT_NEAR(noon.altitude, kPi / 2 - site.latitude + declination, 1e-12);
    EXPECT_NEAR(noon.azimuth, 0, 1e-12);
    glm::dvec3 toNoonSun = sunDirection(noon);
    EXPECT_LT(toNoonSun.y, 0);  // south is -y
    SunAngles morning = sunAngles(declination, 9, site);
    EXPECT_LT(morning.azimuth, 0);
    EXPECT_GT(sunDirection(morning).x, 0);
    EXPECT_NEAR(glm::dot(sunDirection(morning), sunDirection(morning)), 1, 1e-12);
}

// At an equinox the day lasts 12 hours everywhere; at 52.5° N in June about 16.6 hours.
TEST(SolarPosition, DayLengthFollowsLatitudeAndSeason) {
    Site berlin{52.5 * kDegree, -13.4 * kDegree, -15 * kDegree};
    int equinox = 81;  // the IES declination's zero
    EXPECT_NEAR(sunsetSolarTime(equinox, berlin) - sunriseSolarTime(equinox, berlin), 12, 1e-9);
    EXPECT_NEAR(sunsetSolarTime(dayOfYear(6, 21), berlin) - sunriseSolarTime(dayOfYear(6, 21), berlin), 16.6, 0.1);
    EXPECT_NEAR(sunAngles(iesDeclination(equinox), sunriseSolarTime(equinox, berlin), berlin).altitude, 0, 1e-9);
}
