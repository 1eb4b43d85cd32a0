// Where the sun is, with Radiance's conventions (gensky(1), gendaylit(1)): angles in radians, latitude
// north, longitude and standard meridian positive WEST of Greenwich, azimuth measured from south toward
// west; in the scene x points east, y north and z up.
#pragma once
#include <glm/vec3.hpp>

namespace brume {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180;

struct Site {
    // Radiance's defaults (San Francisco), kept in the radians Radiance stores, so that the degrees
    // printed by -defaults (37.815214, 122.040010) are the same.
    double latitude = 0.66;
    double longitude = 2.13;
    double meridian = 120 * kDegree;
};

struct SunAngles {
    double altitude = 0;  // above the horizon
    double azimuth = 0;   // west of south
};

// A time of day on a date: local standard time on the site's meridian, or local solar time.
struct LocalTime {
    int year = 0;  // 0: no year given, the IES formulas are used
    int month = 1, day = 1;
    double hour = 12;
    bool solar = false;
};

// Where the sun is on the celestial sphere at a given time, and the solar time there.
struct SunDeclination {
    double declination = 0;  // radians
    double solarTime = 0;    // hours, 12 at solar noon
};

// Day of the year, 1 on January 1st, as if every year had 365 days.
int dayOfYear(int month, int day);

// The sun's declination and the solar time: without a year by the IES Lighting Handbook's formulas,
// with one by Michalsky (1988), as gensky chooses.
SunDeclination sunDeclination(const LocalTime& time, const Site& site);

// IES Lighting Handbook: declination (radians) on a day of the year.
double iesDeclination(int dayOfYear);
// IES Lighting Handbook (1981): hours from local standard time to solar time on a day of the year, the
// equation of time plus four minutes per degree between the standard meridian and the site.
double iesSolarTimeCorrection(int dayOfYear, const Site& site);

// Altitude and azimuth of the sun for a declination and a solar time at the site's latitude.
SunAngles sunAngles(double declination, double solarTime, const Site& site);

// Unit vector toward the sun (x east, y north, z up).
glm::dvec3 sunDirection(const SunAngles& sun);

// Solar times (hours) of sunrise and sunset, from the IES declination, as gendaylit tests them.
double sunriseSolarTime(int dayOfYear, const Site& site);
double sunsetSolarTime(int dayOfYear, const Site& site);

}  // namespace brume
