#include "sky/sky_command.h"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace brume {

namespace {

// Time zones gensky knows, with their standard meridians in degrees west of Greenwich.
struct TimeZone {
    const char* name;
    double meridian;
};
constexpr TimeZone kTimeZones[] = {
    {"YST", 135}, {"YDT", 120}, {"PST", 120}, {"PDT", 105}, {"MST", 105},  {"MDT", 90},    {"CST", 90},
    {"CDT", 75},  {"EST", 75},  {"EDT", 60},  {"AST", 60},  {"ADT", 45},   {"NST", 52.5},  {"NDT", 37.5},
    {"GMT", 0},   {"BST", -15}, {"CET", -15}, {"CEST", -30}, {"EET", -30}, {"EEST", -45},  {"GST", -60},
    {"GDT", -75}, {"IST", -82.5}, {"IDT", -97.5}, {"JST", -135}, {"NZST", -180}, {"NZDT", -195}};

double timeZoneMeridian(const std::string& zone) {
    std::string upper;
    for (char c : zone) upper += char(std::toupper(static_cast<unsigned char>(c)));
    std::string known;
    for (const TimeZone& z : kTimeZones) {
        if (upper == z.name) return z.meridian * kDegree;
        known += std::string(" ") + z.name;
    }
    throw Error("unknown time zone: " + zone + " (known:" + known + ")");
}

size_t skipDigits(const std::string& s, size_t i) {
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

void warnIfFarFromMeridian(const Site& site) {
    if (std::abs(site.meridian - site.longitude) <= 45 * kDegree) return;
    char text[80];
    std::snprintf(text, sizeof text, "%.1f hours btwn. standard meridian and longitude",
                  (site.longitude - site.meridian) * 12 / kPi);
    warn(text);
}

int toIntIn(const std::string& text, int low, int high, const std::string& what) {
    try {
        size_t used;
        int v = std::stoi(text, &used);
        if (used == text.size() && v >= low && v <= high) return v;
    } catch (const std::exception&) {
    }
    throw Error("bad " + what);
}

}  // namespace

ClockTime parseClockTime(const std::string& text) {
    ClockTime t;
    t.solar = text.rfind('+', 0) == 0;
    size_t start = t.solar ? 1 : 0, hoursEnd = skipDigits(text, start), end = hoursEnd;
    bool colon = end < text.size() && text[end] == ':';
    if (colon || (end < text.size() && text[end] == '.')) end = skipDigits(text, end + 1);
    std::string hours = text.substr(start, hoursEnd - start);
    std::string rest = end > hoursEnd ? text.substr(hoursEnd + 1, end - hoursEnd - 1) : "";  // minutes or decimals
    std::string zone = text.substr(end);
    bool digits = !hours.empty() || (!colon && !rest.empty());
    if (!digits || end - start > 12 || (!zone.empty() && (t.solar || !std::isalpha(static_cast<unsigned char>(zone[0])))))
        throw Error("bad time format: " + text);
    if (colon) t.hour = std::stod(hours) + (rest.empty() ? 0 : std::stod(rest)) / 60;
    else t.hour = std::stod(text.substr(start, end - start));
    if (!zone.empty()) t.meridian = timeZoneMeridian(zone);
    return t;
}

SkyWhen parseWhen(const std::vector<std::string>& words) {
    SkyWhen w;
    if (words.size() < 3) throw Error("arg count");
    if (words[0] == "-ang") {
        w.fromAngles = true;
        w.angles = {toReal("-ang", words[1]) * kDegree, toReal("-ang", words[2]) * kDegree};
        return w;
    }
    w.time.month = toIntIn(words[0], 1, 12, "month");
    w.time.day = toIntIn(words[1], 1, 31, "day");
    ClockTime clock = parseClockTime(words[2]);
    w.time.hour = clock.hour;
    w.time.solar = clock.solar;
    w.meridian = clock.meridian;
    return w;
}

void addSiteOptions(OptionTable& t, double& groundReflectance, Site& site, int& year) {
    t.add("-g", 1, "ground reflectance (default 0.2)",
          [&groundReflectance](const std::vector<std::string>& a) { groundReflectance = toReal("-g", a[0]); });
    auto angle = [](double& to, const char* name) {
        return [&to, name](const std::vector<std::string>& a) { to = toReal(name, a[0]) * kDegree; };
    };
    t.add("-a", 1, "site latitude (degrees north)", angle(site.latitude, "-a"));
    t.add("-o", 1, "site longitude (degrees west)", angle(site.longitude, "-o"));
    t.add("-m", 1, "standard meridian (degrees west; a time zone overrides it)", angle(site.meridian, "-m"));
    t.add("-y", 1, "year: Michalsky's solar position instead of the IES one",
          [&year](const std::vector<std::string>& a) { year = toInt("-y", a[0]); });
}

std::optional<SkyWhen> parseSkyCommand(const std::vector<std::string>& args, const OptionTable& table,
                                       const std::string& usage, Site& site, const int& year) {
    if (args.size() == 1 && args[0] == "-defaults") return std::nullopt;
    SkyWhen when;
    try {
        when = parseWhen(args);
        std::vector<std::string> options(args.begin() + 3, args.end());
        size_t used = table.parse(options);
        if (used < options.size()) throw Error("bad option " + options[used]);
    } catch (const Error& e) {
        throw UsageError(e.what(), usage + table.usage());
    }
    when.time.year = year;
    if (when.meridian) site.meridian = *when.meridian;
    if (!when.fromAngles && !when.time.solar) warnIfFarFromMeridian(site);
    return when;
}

void printSunPosition(double solarTime, double altitude, double azimuth) {
    std::printf("# Local solar time: %.2f\n", solarTime);
    std::printf("# Solar altitude and azimuth: %.1f %.1f\n", altitude, azimuth);
}

void printSolarSource(const std::string& radiance, const glm::dvec3& d, const std::string& diameter) {
    std::printf("\nvoid light solar\n0\n0\n3 %s\n", radiance.c_str());
    std::printf("\nsolar source sun\n0\n0\n4 %f %f %f %s\n", d.x, d.y, d.z, diameter.c_str());
}

double degrees(double radians) { return 180 / kPi * radians; }

void printSiteDefaults(double reflectance, double turbidity, const char* turbidityLabel, const Site& site) {
    std::printf("-g %f\t\t\t# Ground plane reflectance\n", reflectance);
    std::printf("-t %f\t\t\t# %s\n", turbidity, turbidityLabel);
    std::printf("-a %f\t\t\t# Site latitude (degrees)\n", degrees(site.latitude));
    std::printf("-o %f\t\t\t# Site longitude (degrees)\n", degrees(site.longitude));
    std::printf("-m %f\t\t\t# Standard meridian (degrees)\n", degrees(site.meridian));
}

}  // namespace brume
