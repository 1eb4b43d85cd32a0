#include "sky/solar_position.h"

#include <cmath>

namespace brume {

namespace {

// The angle (or time) r brought into [0, period).
double wrap(double r, double period) { return r - period * std::floor(r / period); }

// Days since noon UT on January 1st, 2000 (J2000.0) at a local standard time, counted as Radiance counts
// them: leap years every fourth year from 1949 on.
double daysSinceJ2000(const LocalTime& t, const Site& site) {
    int days = dayOfYear(t.month, t.day) + (t.month > 2 && t.year % 4 == 0) + (t.year - 1949) * 365 +
               (t.year - 1949) / 4;
    double universalHour = t.hour + site.meridian * 12 / kPi;
    return days + universalHour / 24 + (2432916.5 - 2451545.0);
}

// Michalsky (1988), "The Astronomical Almanac's algorithm for approximate solar position (1950-2050)",
// Solar Energy 40(3): ecliptic longitude, obliquity, right ascension and sidereal time.
SunDeclination michalsky(double n, const Site& site) {
    double meanLongitude = wrap((280.460 + 0.9856474 * n) * kDegree, 2 * kPi);
    double meanAnomaly = wrap((357.528 + 0.9856003 * n) * kDegree, 2 * kPi);
    double eclipticLongitude =
        meanLongitude + 1.915 * kDegree * std::sin(meanAnomaly) + 0.020 * kDegree * std::sin(2 * meanAnomaly);
    double obliquity = (23.439 - 4e-7 * n) * kDegree;
    double sinL = std::sin(eclipticLongitude);
    double rightAscension = std::atan2(sinL * std::cos(obliquity), std::cos(eclipticLongitude));
    double universalTime = 24 * (n - std::floor(n)) + 12;
    double greenwichSidereal = 6.697375 + 0.0657098242 * n + universalTime;
    double localSidereal = greenwichSidereal - site.longitude * 12 / kPi;
    return {std::asin(std::sin(obliquity) * sinL), wrap(localSidereal - rightAscension * 12 / kPi + 12, 24)};
}

// Half the length of the day in hours: the hour angle at which the sun's centre crosses the horizon,
// acos(-tan(latitude) tan(declination)). The cosine is rounded to single precision and the angle taken
// as gendaylit takes it, so that times corrected by -i match its output to the last printed digit.
double halfDayHours(int day, const Site& site) {
    float cosine = float(-std::tan(site.latitude) * std::tan(iesDeclination(day)));
    return (kPi / 2 - std::atan2(cosine, std::sqrt(double(1 - cosine * cosine)))) * 180 / (kPi * 15);
}

}  // namespace

int dayOfYear(int month, int day) {
    static constexpr int kDaysBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    return kDaysBefore[month - 1] + day;
}

// IES Lighting Handbook (1981): declination as a sine over the year, 23.45° at the June solstice.
double iesDeclination(int day) { return 0.4093 * std::sin(2 * kPi / 365 * (day - 81)); }

double iesSolarTimeCorrection(int day, const Site& site) {
    return 0.170 * std::sin(4 * kPi / 373 * (day - 80)) - 0.129 * std::sin(2 * kPi / 355 * (day - 8)) +
           12 / kPi * (site.meridian - site.longitude);
}

SunDeclination sunDeclination(const LocalTime& t, const Site& site) {
    if (t.year != 0) {
        // With solar time given, gensky still dates the almanac as if that were standard time.
        SunDeclination d = michalsky(daysSinceJ2000(t, site), site);
        if (t.solar) d.solarTime = t.hour;
        return d;
    }
    int day = dayOfYear(t.month, t.day);
    return {iesDeclination(day), t.solar ? t.hour : t.hour + iesSolarTimeCorrection(day, site)};
}

// Spherical astronomy (IES Lighting Handbook 1981): altitude and azimuth from latitude, declination and
// the sun's angle from local midnight (15° per hour of solar time).
SunAngles sunAngles(double declination, double solarTime, const Site& site) {
    double fromMidnight = solarTime * kPi / 12;
    double sinLat = std::sin(site.latitude), cosLat = std::cos(site.latitude);
    double sinDec = std::sin(declination), cosDec = std::cos(declination);
    return {std::asin(sinLat * sinDec - cosLat * cosDec * std::cos(fromMidnight)),
            -std::atan2(cosDec * std::sin(fromMidnight), -cosLat * sinDec - sinLat * cosDec * std::cos(fromMidnight))};
}

glm::dvec3 sunDirection(const SunAngles& sun) {
    return {-std::sin(sun.azimuth) * std::cos(sun.altitude), -std::cos(sun.azimuth) * std::cos(sun.altitude),
            std::sin(sun.altitude)};
}

double sunriseSolarTime(int day, const Site& site) { return 12 - halfDayHours(day, site); }
double sunsetSolarTime(int day, const Site& site) { return 12 + halfDayHours(day, site); }

}  // namespace brume
