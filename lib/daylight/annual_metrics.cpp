#include "daylight/annual_metrics.h"

#include <algorithm>
#include <numeric>

#include "util/error.h"

namespace brume {

namespace {

int count(const std::vector<bool>& flags) { return int(std::count(flags.begin(), flags.end(), true)); }

void checkYear(const std::vector<bool>& flags, const char* what) {
    if (flags.size() != kHoursInYear) throw Error(std::string(what) + ": " + std::to_string(flags.size()) + " hours, not 8760");
}

// The share (percent) of sensors whose hours at or above `lux` are at least half of `hours`.
double shareReaching(const HourlyIlluminance& e, const std::vector<bool>& hours, double lux) {
    int total = count(hours), reaching = 0;
    for (int s = 0; s < e.sensors; ++s) {
        int n = 0;
        for (size_t c = 0; c < e.hours.size(); ++c) n += hours[e.hours[c]] && e.at(s, int(c)) >= lux;
        reaching += total > 0 && 2 * n >= total;
    }
    return e.sensors ? 100.0 * reaching / e.sensors : 0;
}

}  // namespace

std::vector<bool> eightToSix() {
    std::vector<bool> occupied(kHoursInYear);
    for (int h = 0; h < kHoursInYear; ++h) occupied[h] = h % 24 >= 8 && h % 24 < 18;
    return occupied;
}

std::vector<SensorMetrics> annualMetrics(const HourlyIlluminance& e, const std::vector<bool>& occupied,
                                         const DaylightThresholds& t) {
    checkYear(occupied, "the occupancy schedule");
    int total = count(occupied);
    if (total == 0) throw Error("no occupied hours");
    std::vector<SensorMetrics> out(e.sensors);
    for (int s = 0; s < e.sensors; ++s) {
        double da = 0, cda = 0, lower = 0, band = 0, upper = 0;
        int seen = 0;  // occupied hours with results; the others are dark
        for (size_t c = 0; c < e.hours.size(); ++c) {
            if (!occupied[e.hours[c]]) continue;
            ++seen;
            double v = e.at(s, int(c));
            da += v >= t.target;
            cda += v >= t.target ? 1 : v / t.target;
            lower += v < t.lower;
            band += v >= t.lower && v <= t.upper;
            upper += v > t.upper;
        }
        lower += total - seen;
        double percent = 100.0 / total;
        out[s] = {da * percent, cda * percent, lower * percent, band * percent, upper * percent};
    }
    return out;
}

std::vector<int> hoursAbove(const HourlyIlluminance& e, const std::vector<bool>& occupied, double lux) {
    checkYear(occupied, "the occupancy schedule");
    std::vector<int> out(e.sensors);
    for (int s = 0; s < e.sensors; ++s)
        for (size_t c = 0; c < e.hours.size(); ++c) out[s] += occupied[e.hours[c]] && e.at(s, int(c)) > lux;
    return out;
}

double spatialDaylightAutonomy(const std::vector<SensorMetrics>& m) {
    if (m.empty()) return 0;
    return 100.0 * std::count_if(m.begin(), m.end(), [](const SensorMetrics& s) { return s.da >= 50; }) / m.size();
}

double annualSunlightExposure(const std::vector<int>& above, int hours) {
    if (above.empty()) return 0;
    return 100.0 * std::count_if(above.begin(), above.end(), [&](int h) { return h >= hours; }) / above.size();
}

std::vector<bool> daylightHours(const std::vector<double>& diffuse) {
    if (diffuse.size() != kHoursInYear) throw Error("daylight hours need 8760 values, not " + std::to_string(diffuse.size()));
    std::vector<int> order(kHoursInYear);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return diffuse[a] > diffuse[b]; });
    std::vector<bool> daylight(kHoursInYear);
    for (int i = 0; i < kHoursInYear / 2; ++i) daylight[order[i]] = true;
    return daylight;
}

En17037 en17037(const HourlyIlluminance& e, const std::vector<bool>& daylight) {
    checkYear(daylight, "the daylight hours");
    En17037 r;
    for (int level = 0; level < 3; ++level) {
        r.targetShare[level] = shareReaching(e, daylight, kEnTarget[level]);
        r.minimumShare[level] = shareReaching(e, daylight, kEnMinimum[level]);
        bool target = r.targetShare[level] >= 50, minimum = r.minimumShare[level] >= 95;
        if (target) r.targetLevel = level + 1;
        if (minimum) r.minimumLevel = level + 1;
        if (target && minimum) r.level = level + 1;
    }
    return r;
}

}  // namespace brume
