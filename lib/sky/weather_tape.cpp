#include "sky/weather_tape.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <sstream>
#include <strings.h>

namespace brume {

namespace {

std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

bool startsWithNoCase(const std::string& line, const char* prefix) {
    return strncasecmp(line.c_str(), prefix, std::strlen(prefix)) == 0;
}

// A number filling the whole of `text` (spaces around it allowed), or none.
std::optional<double> number(const std::string& text) {
    const char* s = text.c_str();
    char* end;
    double v = std::strtod(s, &end);
    if (end == s) return std::nullopt;
    while (*end == ' ' || *end == '\t' || *end == '\r') ++end;
    if (*end != '\0' || !std::isfinite(v)) return std::nullopt;
    return v;
}

double required(const std::string& text, const SourceLocation& where, const char* what) {
    std::optional<double> v = number(text);
    if (!v) throw Error(where, std::string("bad ") + what + " '" + shownBytes(text, 40) + "'");
    return *v;
}

// A whole number (a date's or time's field), refused beyond what any date holds.
int integer(const std::string& text, const SourceLocation& where, const char* what) {
    double v = required(text, where, what);
    if (!(std::abs(v) <= 1e6) || v != std::floor(v)) throw Error(where, std::string("bad ") + what + " '" + shownBytes(text, 40) + "'");
    return int(v);
}

// An EPW value, or none where the file gives its missing-value code (`missing` or more).
std::optional<double> epwValue(const std::vector<std::string>& f, size_t field, double missing,
                               const SourceLocation& where, const char* what) {
    if (field > f.size() || f[field - 1].empty()) return std::nullopt;
    double v = required(f[field - 1], where, what);
    if (v >= missing) return std::nullopt;
    return v;
}

// Irradiances (or illuminances) beyond any sky's, and dew points beyond any air's, are mistakes, refused
// before they overflow the sky's arithmetic.
std::optional<double> plausible(std::optional<double> v, double limit, const SourceLocation& where, const char* what) {
    if (v && !(std::abs(*v) <= limit)) throw Error(where, std::string("implausible ") + what + " " + std::to_string(*v));
    return v;
}

void checkDate(int month, int day, double hour, const SourceLocation& where) {
    static constexpr int kDays[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12 || day < 1 || day > kDays[month - 1] || !(hour >= 0 && hour <= 24))
        throw Error(where, "impossible date or time (month " + std::to_string(month) + ", day " + std::to_string(day) +
                               ", hour " + std::to_string(hour) + ")");
}

void checkSite(const WeatherSite& s, const SourceLocation& where) {
    if (!(std::abs(s.latitude) <= 90)) throw Error(where, "latitude outside -90..90");
    if (!(std::abs(s.longitude) <= 180)) throw Error(where, "longitude outside -180..180");
    if (!(std::abs(s.timeZone) <= 12)) throw Error(where, "time zone outside -12..12 hours");
    if (!(s.elevation >= -1000 && s.elevation <= 9999.9)) throw Error(where, "site elevation outside -1000..9999.9 m");
}

}  // namespace

WeatherTape::WeatherTape(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {
    std::string first;
    if (!nextLine(first)) throw Error(SourceLocation{name_, 0}, "empty weather tape");
    if (startsWithNoCase(first, "place ")) readWeaHeader(first);
    else if (startsWithNoCase(first, "LOCATION,")) readEpwHeader(first);
    else throw Error(here(), "neither an EPW file (LOCATION,...) nor a .wea file (place ...)");
}

bool WeatherTape::nextLine(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
}

void WeatherTape::readEpwHeader(const std::string& first) {
    std::vector<std::string> f = splitCommas(first);
    if (f.size() < 10) throw Error(here(), "LOCATION line with " + std::to_string(f.size()) + " fields, not 10");
    site_.city = f[1], site_.state = f[2], site_.country = f[3];
    site_.latitude = required(f[6], here(), "latitude");
    site_.longitude = required(f[7], here(), "longitude");
    site_.timeZone = required(f[8], here(), "time zone");
    site_.elevation = required(f[9], here(), "elevation");
    site_.locationFields = f;
    checkSite(site_, here());
    // Radiance's reader wants these by name; PVGIS writes "HOLIDAYS/DAYLIGHT SAVING" without the S.
    for (const char* heading : {"DESIGN CONDITIONS", "TYPICAL/EXTREME PERIODS", "GROUND TEMPERATURES",
                                "HOLIDAYS/DAYLIGHT SAVING", "COMMENTS 1", "COMMENTS 2", "DATA PERIODS"}) {
        std::string line;
        if (!nextLine(line)) throw Error(here(), std::string("EPW header ends before its ") + heading + " line");
        if (!startsWithNoCase(line, heading))
            throw Error(here(), std::string("expected the EPW header's ") + heading + " line, found '" + shownBytes(line, 40) + "'");
        if (std::string(heading) == "DATA PERIODS") {
            std::vector<std::string> p = splitCommas(line);
            std::optional<double> periods = p.size() > 2 ? number(p[1]) : std::nullopt;
            std::optional<double> perHour = p.size() > 2 ? number(p[2]) : std::nullopt;
            if (!periods || !perHour || *perHour < 1 || *perHour > 60)
                throw Error(here(), "bad DATA PERIODS line (periods, records per hour)");
            if (*periods != 1) warn(here().str() + ": reading the first data period only");
            site_.recordsPerHour = int(*perHour);
        }
    }
}

void WeatherTape::readWeaHeader(const std::string& first) {
    std::string place = first.substr(6);
    size_t underscore = place.find('_');
    site_.city = place.substr(0, underscore);
    if (underscore != std::string::npos) site_.country = place.substr(underscore + 1);
    auto value = [&](const char* key) {
        std::string line;
        if (!nextLine(line)) throw Error(here(), std::string(".wea header ends before its ") + key + " line");
        std::istringstream words(line);
        std::string word, rest;
        words >> word >> rest;
        if (word != key) throw Error(here(), std::string("expected the .wea header's ") + key + " line, found '" + shownBytes(line, 40) + "'");
        return required(rest, here(), key);
    };
    site_.latitude = value("latitude");
    site_.longitude = -value("longitude");         // .wea: degrees west
    site_.timeZone = -value("time_zone") / 15;     // .wea: the standard meridian, degrees west
    site_.elevation = value("site_elevation");
    checkSite(site_, here());
    double units = value("weather_data_file_units");
    if (units != 1 && units != 2 && units != 3)
        throw Error(here(), "weather_data_file_units must be 1, 2 or 3");
    units_ = WeatherUnits(int(units));
}

std::optional<WeatherRecord> WeatherTape::next() {
    std::string line;
    while (nextLine(line))
        if (line.find_first_not_of(" \t") != std::string::npos)
            return units_ == WeatherUnits::Epw ? parseEpwRecord(line) : parseWeaRecord(line);
    return std::nullopt;
}

WeatherRecord WeatherTape::parseEpwRecord(const std::string& line) const {
    std::vector<std::string> f = splitCommas(line);
    WeatherRecord r;
    r.where = here();
    if (f.size() < 16) throw Error(r.where, "EPW record with " + std::to_string(f.size()) + " fields, not 35");
    r.year = integer(f[0], r.where, "year");
    r.month = integer(f[1], r.where, "month");
    r.day = integer(f[2], r.where, "day");
    int hour = integer(f[3], r.where, "hour");
    r.minute = integer(f[4], r.where, "minute");
    // Hourly records stand for the hour that ends at `hour`; shorter ones for the instant they end at, as
    // Radiance's reader takes them.
    r.hour = hour - 1 + (site_.recordsPerHour == 1 ? 0.5 : r.minute / 60.0);
    checkDate(r.month, r.day, r.hour, r.where);
    r.dewPoint = plausible(epwValue(f, 8, 99.9, r.where, "dew point"), 100, r.where, "dew point");
    r.direct = plausible(epwValue(f, 15, 9999, r.where, "direct normal irradiance"), 1e7, r.where, "direct normal irradiance");
    r.diffuse = plausible(epwValue(f, 16, 9999, r.where, "diffuse horizontal irradiance"), 1e7, r.where, "diffuse horizontal irradiance");
    r.diffuseIlluminance = plausible(epwValue(f, 19, 999900, r.where, "diffuse horizontal illuminance"), 1e7, r.where,
                                     "diffuse horizontal illuminance");
    // As written, missing-value codes included: epw2wea -a copies them.
    r.skyCover = epwValue(f, 23, INFINITY, r.where, "total sky cover");
    r.aerosolDepth = epwValue(f, 30, INFINITY, r.where, "aerosol optical depth");
    return r;
}

WeatherRecord WeatherTape::parseWeaRecord(const std::string& line) const {
    WeatherRecord r;
    r.where = here();
    std::istringstream in(line);
    std::string month, day, hour, direct, diffuse, aerosol, cover;
    if (!(in >> month >> day >> hour >> direct >> diffuse))
        throw Error(r.where, "a .wea record is 'month day hour direct diffuse', not '" + shownBytes(line, 60) + "'");
    r.month = integer(month, r.where, "month");
    r.day = integer(day, r.where, "day");
    r.hour = required(hour, r.where, "hour");
    checkDate(r.month, r.day, r.hour, r.where);
    double a = required(direct, r.where, "direct value"), b = required(diffuse, r.where, "diffuse value");
    r.direct = plausible(a, 1e7, r.where, "direct value");
    r.diffuse = plausible(b, 1e7, r.where, "diffuse value");
    if (in >> aerosol >> cover) r.aerosolDepth = required(aerosol, r.where, "aerosol depth"), r.skyCover = required(cover, r.where, "sky cover");
    return r;
}

}  // namespace brume
