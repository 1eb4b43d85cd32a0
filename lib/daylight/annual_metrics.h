// Annual daylight metrics from hourly illuminances, as building codes define them and as Ladybug Tools'
// honeybee-radiance-postprocess computes them (the numbers practitioners compare with): per sensor daylight
// autonomy (DA), continuous DA, useful daylight illuminance (UDI) bands and hours of direct sun; per grid
// LEED's spatial daylight autonomy (sDA300/50%) and annual sunlight exposure (ASE1000,250), and EN 17037's
// daylight provision. Occupied hours without results (the sun down) count as dark hours.
#pragma once
#include <cstddef>
#include <vector>

namespace brume {

inline constexpr int kHoursInYear = 8760;

// Illuminances (lx) of sensors at some hours of the year (0..8759, local standard time): the columns of an
// annual matrix, often the hours with the sun up only.
struct HourlyIlluminance {
    int sensors = 0;
    std::vector<int> hours;
    std::vector<float> lux;  // sensors × hours, sensor by sensor
    float at(int sensor, int column) const { return lux[std::size_t(sensor) * hours.size() + column]; }
};

// Occupied hours of the year: 8 am to 6 pm (hours 8 to 17) every day, 3650 hours, the default of LEED's
// and Honeybee's annual studies.
std::vector<bool> eightToSix();

struct DaylightThresholds {
    double target = 300;  // DA, cDA
    double lower = 100;   // UDI's band: lower <= E <= upper
    double upper = 3000;
};

struct SensorMetrics {
    double da = 0, cda = 0, udiLower = 0, udi = 0, udiUpper = 0;  // percentages of the occupied hours
};

// Per sensor, over the occupied hours (`occupied`, 8760 flags): DA (E >= target), cDA (E / target below
// it), UDI-lower (E < lower, dark hours included), UDI (lower <= E <= upper), UDI-upper (E > upper).
std::vector<SensorMetrics> annualMetrics(const HourlyIlluminance& e, const std::vector<bool>& occupied,
                                         const DaylightThresholds& t);

// Per sensor, the occupied hours with more than `lux` (ASE's direct-sun illuminance above 1000 lx).
std::vector<int> hoursAbove(const HourlyIlluminance& e, const std::vector<bool>& occupied, double lux);

// LEED v4.1's shares of sensors, in percent: sDA, those with DA >= 50; ASE, those with `hoursAbove` >=
// `hours` (Honeybee reads "more than 250 hours" as 250 or more). Blinds are not operated.
double spatialDaylightAutonomy(const std::vector<SensorMetrics>& m);
double annualSunlightExposure(const std::vector<int>& hoursAbove, int hours = 250);

// EN 17037: the daylight hours are the half of the year (4380 hours) with the most diffuse horizontal light
// (ties to the earlier hour), from 8760 values.
std::vector<bool> daylightHours(const std::vector<double>& diffuseHorizontal);

// EN 17037's daylight provision over its daylight hours: for each level (minimum, medium, high), the
// share of sensors reaching the target illuminance (300, 500, 750 lx) and the minimum illuminance (100,
// 300, 500 lx) for half the hours; a level is met where the target's share is at least 50 % and the
// minimum's at least 95 %. `level`: the highest level met by each criterion alone (0: none), as Honeybee
// reports them, and by both.
struct En17037 {
    double targetShare[3] = {0, 0, 0}, minimumShare[3] = {0, 0, 0};  // percent of sensors
    int targetLevel = 0, minimumLevel = 0, level = 0;
};
inline constexpr double kEnTarget[3] = {300, 500, 750}, kEnMinimum[3] = {100, 300, 500};
En17037 en17037(const HourlyIlluminance& e, const std::vector<bool>& daylight);

}  // namespace brume
