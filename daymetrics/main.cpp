// daymetrics: annual daylight metrics from hourly illuminances (an annual matrix: sensors × hours), as
// building codes define them (see man/daymetrics.1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "daylight/annual_metrics.h"
#include "daylight/sensor_plan.h"
#include "io/ray_reader.h"
#include "matrix/matrix_file.h"
#include "matrix/symbolic_components.h"
#include "spectrum/colorimetry.h"
#include "sky/weather_tape.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"
#include "util/pending_file.h"

using namespace brume;

namespace {

const std::string kUsage = "usage: daymetrics [options] illuminance.mtx\n";

struct Options {
    DaylightThresholds thresholds;
    std::string hours, schedule, direct, weather, grid, points, maps;
    double sunLux = 1000;
    int sunHours = 250;
    bool melanopic = false;
    std::optional<double> target;  // -t, else the quantity's default
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    t.addBool("-melanopic", o.melanopic, "melanopic EDI rather than illuminance: the share of occupied hours with -t or more");
    t.add("-t", 1, "DA's threshold, lx (default 300; melanopic EDI: 250)", [&o](const auto& a) { o.target = toReal("-t", a[0]); });
    t.add("-lt", 1, "UDI's lower threshold, lx (default 100)", [&o](const auto& a) { o.thresholds.lower = toReal("-lt", a[0]); });
    t.add("-ut", 1, "UDI's upper threshold, lx (default 3000)", [&o](const auto& a) { o.thresholds.upper = toReal("-ut", a[0]); });
    t.add("-hours", 1, "the columns' hours of the year, one a line (Honeybee's sun-up-hours.txt)", [&o](const auto& a) { o.hours = a[0]; });
    t.add("-schedule", 1, "8760 occupancy values, one a line, > 0 occupied (default: 8 am to 6 pm)", [&o](const auto& a) { o.schedule = a[0]; });
    t.add("-direct", 1, "illuminance from the direct sun alone (sensors × the same hours), for ASE", [&o](const auto& a) { o.direct = a[0]; });
    t.add("-al", 1, "ASE's illuminance, lx (default 1000)", [&o](const auto& a) { o.sunLux = toReal("-al", a[0]); });
    t.add("-ah", 1, "ASE's hours (default 250)", [&o](const auto& a) { o.sunHours = toInt("-ah", a[0]); });
    t.add("-weather", 1, "a weather tape (.wea or .epw) whose brightest half of the year is EN 17037's daylight hours",
          [&o](const auto& a) { o.weather = a[0]; });
    t.add("-g", 1, "write the grid's metrics (sDA, ASE, EN 17037) to this CSV file", [&o](const auto& a) { o.grid = a[0]; });
    t.add("-pts", 1, "the sensors (x y z dx dy dz a line, as rtrace reads them), for -maps", [&o](const auto& a) { o.points = a[0]; });
    t.add("-maps", 1, "write each metric over the plan of the sensors (-pts) to prefix_metric.hdr", [&o](const auto& a) { o.maps = a[0]; });
    return t;
}

// One value per line (blank lines and # comments skipped), each named by file:line when it is no number.
std::vector<double> readColumn(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open '" + path + "'");
    std::vector<double> values;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        std::istringstream words(line);
        std::string w;
        if (!(words >> w) || w[0] == '#') continue;
        char* end;
        double v = std::strtod(w.c_str(), &end);
        if (*end || !std::isfinite(v)) throw Error(SourceLocation{path, n}, "not a number: '" + shownBytes(w, 30) + "'");
        values.push_back(v);
    }
    return values;
}

// The weights that turn a matrix's components into lux: illuminance (RGB irradiance: Honeybee's 179 lm/W × Radiance's
// Y; spectral: each band's share of ȳ × 179), or melanopic EDI (CIE S 026: Radiance's melanopic value, rmtxop -c
// M's, times ∫ȳ·D65 / ∫s_mel·D65, so that daylight D65 has the same EDI as illuminance), which only colours give.
std::vector<double> luxWeights(const Matrix& m, bool melanopic) {
    if (melanopic) {
        if (m.comps == 1)
            throw Error("one component may be illuminance or melanopic: -melanopic needs the RGB or spectral matrix (without rmtxop -c)");
        std::vector<double> w = symbolWeights("M", m);
        for (double& v : w) v *= observerWeights().melanopicToDaylight;
        return w;
    }
    if (m.comps == 1) return {1};
    if (m.comps == 3) return {47.4, 119.9, 11.6};
    return symbolWeights("Y", m);
}

HourlyIlluminance illuminance(const std::string& spec, const std::vector<int>& hours, bool melanopic = false) {
    Matrix m = readMatrix(spec);
    if (m.comps == 2) throw Error(spec + ": illuminance in 1 component (lx), 3 (RGB) or more (spectral), not 2");
    try {
        m = transformed(m, luxWeights(m, melanopic));
    } catch (const Error& e) {
        throw Error(spec + ": " + e.what());
    }
    HourlyIlluminance e;
    e.sensors = m.rows;
    if (!hours.empty()) e.hours = hours;
    else if (m.cols == kHoursInYear)
        for (int h = 0; h < kHoursInYear; ++h) e.hours.push_back(h);
    else throw Error(spec + ": " + std::to_string(m.cols) + " columns, not 8760: say which hours they are (-hours)");
    if (int(e.hours.size()) != m.cols)
        throw Error(spec + ": " + std::to_string(m.cols) + " columns for " + std::to_string(e.hours.size()) + " hours");
    e.lux = std::move(m.values);
    return e;
}

std::vector<int> columnHours(const std::string& path) {
    std::vector<int> hours;
    for (double h : readColumn(path)) {
        if (!(h >= 0 && h < kHoursInYear)) throw Error(path + ": hour " + std::to_string(h) + " outside the year");
        hours.push_back(int(h));  // 8.5, the middle of 8:00-9:00, is hour 8
    }
    return hours;
}

std::vector<double> diffuseOfYear(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open weather tape '" + path + "'");
    WeatherTape tape(in, path);
    std::vector<double> diffuse;
    while (std::optional<WeatherRecord> r = tape.next())
        diffuse.push_back(r->diffuseIlluminance.value_or(r->diffuse.value_or(0)));
    return diffuse;
}

std::vector<dvec3> sensorPoints(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open '" + path + "'");
    RayReader reader(in, 'a', path);
    std::vector<dvec3> points;
    for (std::array<double, 6> r; reader.next(r);) points.push_back(dvec3(r[0], r[1], r[2]));
    return points;
}

// One value a sensor, drawn over the plan as prefix_name.hdr.
struct MapColumn {
    std::string name, what;
    std::vector<double> values;
};

void writeMaps(const Options& o, const std::vector<MapColumn>& columns, const std::string& command) {
    std::vector<dvec3> points = sensorPoints(o.points);
    const size_t sensors = columns.front().values.size();
    if (points.size() != sensors)
        throw Error(o.points + ": " + std::to_string(points.size()) + " sensors for a matrix of " + std::to_string(sensors));
    SensorPlan plan(points);
    for (const MapColumn& c : columns) {
        Picture p = plan.map(c.values, {command, "DAYMETRICS=" + c.what + " (0 outside the sensors' cells)"});
        writeWhole(o.maps + "_" + c.name + ".hdr", [&](std::ostream& out) { writeRadiancePicture(out, p); });
    }
}

std::vector<double> column(const std::vector<SensorMetrics>& metrics, double SensorMetrics::*value) {
    std::vector<double> values;
    for (const SensorMetrics& m : metrics) values.push_back(m.*value);
    return values;
}

std::string twoDecimals(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", x);
    return text;
}

int occupiedCount(const std::vector<bool>& occupied) { return int(std::count(occupied.begin(), occupied.end(), true)); }

// The year as daylight: DA, cDA, UDI bands per sensor (the direct sun's hours with -direct), sDA, ASE and EN
// 17037 per grid.
void writeDaylight(const Options& o, const HourlyIlluminance& e, const std::vector<int>& hours,
                   const std::vector<bool>& occupied, const std::string& command) {
    DaylightThresholds thresholds = o.thresholds;
    thresholds.target = o.target.value_or(300);
    std::vector<SensorMetrics> metrics = annualMetrics(e, occupied, thresholds);
    std::vector<int> sun;
    if (!o.direct.empty()) {
        HourlyIlluminance d = illuminance(o.direct, hours);
        if (d.sensors != e.sensors) throw Error(o.direct + ": " + std::to_string(d.sensors) + " sensors, not " + std::to_string(e.sensors));
        sun = hoursAbove(d, occupied, o.sunLux);
    }
    std::optional<En17037> en;
    if (!o.weather.empty()) en = en17037(e, daylightHours(diffuseOfYear(o.weather)));
    if (!o.maps.empty()) {
        std::vector<MapColumn> maps = {
            {"da", "daylight autonomy, percent of the occupied hours", column(metrics, &SensorMetrics::da)},
            {"cda", "continuous daylight autonomy, percent of the occupied hours", column(metrics, &SensorMetrics::cda)},
            {"udi_lower", "UDI below the lower threshold, percent of the occupied hours", column(metrics, &SensorMetrics::udiLower)},
            {"udi", "useful daylight illuminance, percent of the occupied hours", column(metrics, &SensorMetrics::udi)},
            {"udi_upper", "UDI above the upper threshold, percent of the occupied hours", column(metrics, &SensorMetrics::udiUpper)}};
        if (!sun.empty())
            maps.push_back({"sun_hours", "occupied hours of direct sun above the ASE illuminance", {sun.begin(), sun.end()}});
        writeMaps(o, maps, command);
    }
    std::printf("sensor,da,cda,udi_lower,udi,udi_upper%s\n", sun.empty() ? "" : ",sun_hours");
    for (int s = 0; s < e.sensors; ++s) {
        const SensorMetrics& m = metrics[s];
        std::printf("%d,%.2f,%.2f,%.2f,%.2f,%.2f", s, m.da, m.cda, m.udiLower, m.udi, m.udiUpper);
        if (!sun.empty()) std::printf(",%d", sun[s]);
        std::printf("\n");
    }
    if (o.grid.empty()) return;
    writeWhole(o.grid, [&](std::ostream& out) {
        out << "metric,value\nsensors," << e.sensors << "\noccupied_hours," << occupiedCount(occupied) << "\nsda,"
            << twoDecimals(spatialDaylightAutonomy(metrics)) << "\n";
        if (!sun.empty()) out << "ase," << twoDecimals(annualSunlightExposure(sun, o.sunHours)) << "\n";
        if (!en) return;
        for (int l = 0; l < 3; ++l)
            out << "en17037_target_" << kEnTarget[l] << "," << twoDecimals(en->targetShare[l]) << "\nen17037_minimum_"
                << kEnMinimum[l] << "," << twoDecimals(en->minimumShare[l]) << "\n";
        out << "en17037_target_level," << en->targetLevel << "\nen17037_minimum_level," << en->minimumLevel
            << "\nen17037_level," << en->level << "\n";
    });
}

// The year as melanopic EDI: per sensor the share of the occupied hours with at least the threshold, and
// their number; per grid the mean share and the share of sensors reaching it half the time.
void writeMelanopic(const Options& o, const HourlyIlluminance& e, const std::vector<bool>& occupied,
                    const std::string& command) {
    if (!o.direct.empty() || !o.weather.empty()) throw Error("-direct and -weather are daylight's, not -melanopic's");
    DaylightThresholds thresholds;
    thresholds.target = o.target.value_or(250);
    std::vector<SensorMetrics> metrics = annualMetrics(e, occupied, thresholds);
    if (!o.maps.empty())
        writeMaps(o, {{"melanopic_da", "share of the occupied hours with melanopic EDI of " + std::to_string(int(thresholds.target)) +
                                           " lx or more, percent", column(metrics, &SensorMetrics::da)}},
                  command);
    const int occupiedHours = occupiedCount(occupied);
    std::printf("sensor,melanopic_da,melanopic_hours\n");
    for (int s = 0; s < e.sensors; ++s)
        std::printf("%d,%.2f,%ld\n", s, metrics[s].da, std::lround(metrics[s].da * occupiedHours / 100));
    if (o.grid.empty()) return;
    double mean = 0;
    for (const SensorMetrics& m : metrics) mean += m.da / e.sensors;
    writeWhole(o.grid, [&](std::ostream& out) {
        out << "metric,value\nsensors," << e.sensors << "\noccupied_hours," << occupiedHours << "\nmelanopic_threshold,"
            << thresholds.target << "\nmelanopic_da_mean," << twoDecimals(mean) << "\nmelanopic_sda,"
            << twoDecimals(spatialDaylightAutonomy(metrics)) << "\n";
    });
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::vector<std::string> operands = operandsAfterOptions(table, argc, argv, kUsage);
    if (operands.size() != 1) throw UsageError("one illuminance matrix", kUsage + table.usage());
    if (o.maps.empty() != o.points.empty()) throw UsageError("-maps and -pts go together", kUsage + table.usage());
    std::vector<int> hours = o.hours.empty() ? std::vector<int>{} : columnHours(o.hours);
    std::vector<bool> occupied = eightToSix();
    if (!o.schedule.empty()) {
        std::vector<double> values = readColumn(o.schedule);
        if (values.size() != kHoursInYear) throw Error(o.schedule + ": " + std::to_string(values.size()) + " values, not 8760");
        for (int h = 0; h < kHoursInYear; ++h) occupied[h] = values[h] > 0;
    }
    HourlyIlluminance e = illuminance(operands[0], hours, o.melanopic);
    const std::string command = commandLine(std::vector<std::string>(argv, argv + argc));
    if (o.melanopic) writeMelanopic(o, e, occupied, command);
    else writeDaylight(o, e, hours, occupied, command);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
