// What gensky and gendaylit share on their command lines and in the scene text they write.
#pragma once
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sky/solar_position.h"
#include "util/options.h"

namespace brume {

// A time as gensky(1) reads it: decimal hours ("14.5") or hours and minutes ("14:30"), preceded by '+'
// for local solar time, or followed by a time zone ("14:30EDT") that sets the standard meridian.
struct ClockTime {
    double hour = 0;
    bool solar = false;
    std::optional<double> meridian;  // radians west, from the time zone
};
ClockTime parseClockTime(const std::string& text);

// The first three words: "month day time", or "-ang altitude azimuth" (degrees; azimuth west of south).
struct SkyWhen {
    bool fromAngles = false;
    SunAngles angles;                 // with -ang
    LocalTime time;                   // otherwise
    std::optional<double> meridian;   // from a time zone
};
SkyWhen parseWhen(const std::vector<std::string>& words);

// -g ground reflectance, -a latitude, -o longitude, -m meridian (degrees, west positive) and -y year.
void addSiteOptions(OptionTable& table, double& groundReflectance, Site& site, int& year);

// gensky's and gendaylit's command line (argv without the program): "-defaults" alone gives nothing;
// otherwise the when words, then the options of `table`, which set `site` and `year`. The year goes into
// the time and a time zone's meridian into `site`; a site more than 3 hours from its meridian is warned
// about. Throws UsageError (with `usage` and the options) on a mistake.
std::optional<SkyWhen> parseSkyCommand(const std::vector<std::string>& args, const OptionTable& table,
                                       const std::string& usage, Site& site, const int& year);

// "# Local solar time: ..." and "# Solar altitude and azimuth: ..." (degrees).
void printSunPosition(double solarTime, double altitude, double azimuth);
// Degrees as gensky computes them, 180/π × x. gendaylit computes x × 180 / π, which differs in the last
// bit for some angles and so prints some halves the other way (-ang -2.75: -2.7 in gendaylit, -2.8
// by this): each program converts as Radiance's does.
double degrees(double radians);
// The sun as a `light` material and a `source` of the given diameter (degrees, as printed).
void printSolarSource(const std::string& radiance, const glm::dvec3& direction, const std::string& diameter);
// The -defaults lines for ground reflectance, turbidity (with its label), latitude, longitude, meridian.
void printSiteDefaults(double reflectance, double turbidity, const char* turbidityLabel, const Site& site);

}  // namespace brume
