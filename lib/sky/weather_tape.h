// Weather tapes, as Radiance's gendaymtx and epw2wea read them: EnergyPlus weather files (.epw: a LOCATION
// line, seven more header lines, then comma-separated records) and DAYSIM's .wea files (a six-line header,
// then "month day hour direct diffuse" records). Records are read one at a time, so a tape may come from a
// pipe; every error names the file and line.
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "util/error.h"

namespace brume {

// What a tape's two irradiance columns hold: an EPW file's fields by name, or a .wea file's
// weather_data_file_units (1, 2 or 3).
enum class WeatherUnits {
    Epw = 0,
    DirectNormalIrradiance = 1,      // W/m², direct normal and diffuse horizontal
    DirectHorizontalIrradiance = 2,  // W/m², direct horizontal and diffuse horizontal
    DirectNormalIlluminance = 3,     // lx, direct normal and diffuse horizontal
};

struct WeatherSite {
    std::string city, state, country;
    double latitude = 0;   // degrees north
    double longitude = 0;  // degrees EAST, as EPW files give it (.wea files give it west; read negated)
    double timeZone = 0;   // hours east of Greenwich
    double elevation = 0;  // m
    // An EPW file's LOCATION line split at its commas, as written (epw2wea copies some fields verbatim).
    std::vector<std::string> locationFields;
    int recordsPerHour = 1;  // an EPW file's DATA PERIODS
};

struct WeatherRecord {
    SourceLocation where;
    int year = 0, month = 1, day = 1;  // month 1..12
    double hour = 0;  // local standard time, decimal hours: the middle of an hourly record (12.5 for 12:00-13:00)
    int minute = 0;   // an EPW record's minute field
    // Missing values (EPW's codes: 9999 for irradiance, 99.9 for the dew point) are empty.
    std::optional<double> dewPoint;  // °C
    std::optional<double> direct;    // as WeatherUnits says; EPW files: direct normal irradiance
    std::optional<double> diffuse;   // diffuse horizontal
    std::optional<double> diffuseIlluminance;  // EPW files: diffuse horizontal illuminance (lx)
    std::optional<double> aerosolDepth;  // EPW field 29 (thousandths), epw2wea -a
    std::optional<double> skyCover;      // EPW field 23, tenths
};

class WeatherTape {
public:
    // Reads the header; throws Error naming `name` and the line on anything malformed.
    WeatherTape(std::istream& in, std::string name);
    const WeatherSite& site() const { return site_; }
    WeatherUnits units() const { return units_; }
    // The next record, or none at the end. Throws Error on a malformed record or an impossible date.
    std::optional<WeatherRecord> next();

private:
    void readEpwHeader(const std::string& first);
    void readWeaHeader(const std::string& first);
    bool nextLine(std::string& line);
    SourceLocation here() const { return {name_, line_}; }
    WeatherRecord parseEpwRecord(const std::string& line) const;
    WeatherRecord parseWeaRecord(const std::string& line) const;

    std::istream& in_;
    std::string name_;
    int line_ = 0;
    WeatherSite site_;
    WeatherUnits units_ = WeatherUnits::Epw;
};

}  // namespace brume
