#include "sky/sky_matrix.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sky/perez.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr double kEfficacy = 179;           // lm/W: Radiance's white light
constexpr double kSunDiameter = 0.533;      // degrees
constexpr double kTiny = 1e-6;

// Radiance's luminance of an RGB triple (its default primaries).
double brightness(const Rgb& c) { return 0.265074126 * c[0] + 0.670114631 * c[1] + 0.064811243 * c[2]; }

glm::dvec3 direction(double altitude, double azimuth) {
    return {std::cos(altitude) * std::sin(azimuth), std::cos(altitude) * std::cos(azimuth), std::sin(altitude)};
}

bool photometric(WeatherUnits u) { return u == WeatherUnits::DirectNormalIlluminance; }

PerezSkyCondition limited(PerezSkyCondition c, double maxClearness) {
    c.clearness = std::clamp(c.clearness, 1.0, maxClearness);
    c.brightness = std::clamp(c.brightness, 0.01, 0.6);
    return c;
}

// Perez et al. (1990)'s irradiances from illuminances, by gendaymtx's iteration: efficacies from a guess of
// the sky's condition, the condition from the irradiances they give, until both irradiances settle within
// 10 W/m² (at most five rounds).
PerezSkyCondition conditionFromIlluminance(double directLux, double diffuseLux, double zenith, int day, double water,
                                           double& direct, double& diffuse) {
    diffuse = diffuseLux * kSolarConstant / (kSolarConstantLux);
    direct = directLux * kSolarConstant / (kSolarConstantLux);
    PerezSkyCondition c = limited(perezSkyCondition(direct, diffuse, zenith, day), 12);
    double lastDiffuse = 0.1, lastDirect = 0.1;
    for (int round = 0; round < 5 && (std::abs(diffuse - lastDiffuse) > 10 || std::abs(direct - lastDirect) > 10); ++round) {
        lastDiffuse = diffuse, lastDirect = direct;
        diffuse = diffuseLux / diffuseEfficacy(c, zenith, water);
        double efficacy = directEfficacy(c, zenith, water);
        direct = efficacy > 0.1 ? directLux / efficacy : efficacy;
        c = limited(perezSkyCondition(direct, diffuse, zenith, day), 12);
    }
    return c;
}

}  // namespace

SkySteps::SkySteps(const WeatherSite& site, WeatherUnits units, const SkyMatrixOptions& options)
    : units_(units), options_(options), patches_(options.subdivisions) {
    site_.latitude = site.latitude * kDegree;
    site_.longitude = -site.longitude * kDegree;
    site_.meridian = -15 * site.timeZone * kDegree;
}

// gendaymtx's: the mean of the record's dew point and the two before it, where the tape has dew points.
double SkySteps::dewPoint(const WeatherRecord& r) {
    if (!r.dewPoint) {
        dewHistory_[0] = -100;
        return dewPoint_;
    }
    float d = float(*r.dewPoint);  // summed in single precision, as gendaymtx sums them
    if (dewHistory_[0] < -99) dewHistory_[0] = dewHistory_[1] = d;
    dewPoint_ = (1.0 / 3.0) * (dewHistory_[0] + dewHistory_[1] + d);
    dewHistory_[0] = dewHistory_[1], dewHistory_[1] = d;
    return dewPoint_;
}

std::optional<SkyStep> SkySteps::step(const WeatherRecord& r) {
    double dew = dewPoint(r);
    int day;
    if (r.month == 2 && r.day == 29) day = 60, leapDay_ = true;
    else day = dayOfYear(r.month, r.day) + leapDay_;
    double solarTime = r.hour + iesSolarTimeCorrection(day, site_);
    if (options_.interval > 0) {
        double half = options_.interval / 120, rise = sunriseSolarTime(dayOfYear(r.month, r.day), site_),
               set = sunsetSolarTime(dayOfYear(r.month, r.day), site_);
        if (std::abs(rise - solarTime) <= half) solarTime = (solarTime + half + rise) / 2;
        else if (std::abs(set - solarTime) < half) solarTime = (solarTime - half + set) / 2;
    }
    SunAngles sun = sunAngles(iesDeclination(day), solarTime, site_);
    SkyStep s;
    s.record = r;
    s.sunInSky = sun.altitude > -kSunDiameter / 2 * kDegree;
    if (options_.sunHoursOnly && !s.sunInSky) return std::nullopt;
    // East of north, the sky turned by -r.
    double azimuth = sun.azimuth + kPi - options_.rotation * kDegree;
    s.minuteOfYear = 24 * 60 * (day - 1) + int(r.hour * 60 + 0.5);
    s.sunDirection = direction(sun.altitude, azimuth);
    s.patches.assign(3 * size_t(patches_.size()), 0.f);
    if (!r.direct || !r.diffuse) throw Error(r.where, "missing required irradiances");
    // Radiance reads the values in single precision.
    double direct = float(*r.direct), diffuse = float(*r.diffuse);
    if (units_ == WeatherUnits::DirectHorizontalIrradiance) {
        float global = float(direct) + float(diffuse);
        direct = float(global - float(diffuse));
    }
    if (direct + diffuse <= 1e-4) {
        s.dark = true;
        return s;
    }
    if (!s.sunInSky && direct > (photometric(units_) ? 20 * kEfficacy : 20)) {
        char when[64];
        std::snprintf(when, sizeof when, "unusually bright at %.1f on %d-%d", r.hour, r.month, r.day);
        warn(when);
    }
    if (units_ == WeatherUnits::DirectHorizontalIrradiance && sun.altitude > kTiny) direct /= std::sin(sun.altitude);
    computeSky(s, direct, diffuse, Sky{sun.altitude, azimuth, day, dew});
    addSun(s, sun.altitude, azimuth);
    return s;
}

void SkySteps::computeSky(SkyStep& s, double direct, double diffuse, const Sky& at) const {
    double water = precipitableWater(at.dewPoint);
    // The circumsolar peak kept off the zenith, the sun not below the horizon.
    double zenith = at.altitude <= 0 ? kPi / 2 : at.altitude >= 87 * kDegree ? 3 * kDegree : kPi / 2 - at.altitude;
    PerezSkyCondition c;
    double diffuseLux, directLux;
    if (photometric(units_)) {
        diffuseLux = diffuse, directLux = direct;
        c = conditionFromIlluminance(directLux, diffuseLux, zenith, at.day, water, direct, diffuse);
    } else {
        c = limited(perezSkyCondition(direct, diffuse, zenith, at.day), 11.9);
        diffuseLux = diffuse * diffuseEfficacy(c, zenith, water);
        directLux = direct * directEfficacy(c, zenith, water);
    }
    if (options_.solarRadiance) diffuseLux = diffuse * kEfficacy, directLux = direct * kEfficacy;
    s.directIlluminance = directLux;
    // The ground: a Lambertian reflector of the global illuminance.
    float ground = float(diffuseLux);
    if (at.altitude > 0) ground = float(ground + directLux * std::sin(at.altitude));
    ground = float(ground * (1 / kPi / kEfficacy));
    for (int k = 0; k < 3; ++k) s.patches[k] = ground * float(options_.groundReflectance[k]);
    if (brightness(options_.skyColour) <= 1e-4) return;
    PerezCoefficients coefficients = perezCoefficients(zenith, c, TablePrecision::Double);
    double horizontal = 0;  // the relative luminances' illuminance on the ground
    for (int i = 1; i < patches_.size(); ++i) {
        const SkyPatch& p = patches_[i];
        double fromZenith = kPi / 2 - p.altitude;
        double cosGamma = std::cos(zenith) * std::cos(fromZenith) +
                          std::sin(zenith) * std::sin(fromZenith) * std::cos(std::abs(p.azimuth - at.azimuth));
        float l = float(perezRelativeLuminance(coefficients, fromZenith, std::acos(std::clamp(cosGamma, -1.0, 1.0))));
        s.patches[3 * i] = std::max(l, 0.f);
        horizontal += s.patches[3 * i] * tabulatedSine(p.altitude) * p.solidAngle;
    }
    if (horizontal <= kTiny) {  // no sky: a uniform one
        for (int i = 1; i < patches_.size(); ++i) s.patches[3 * i] = 1;
        horizontal = kPi;
    }
    double scale = diffuseLux / horizontal * (1 / kEfficacy);
    for (int i = 1; i < patches_.size(); ++i) {
        float v = float(s.patches[3 * i] * scale);
        for (int k = 0; k < 3; ++k) s.patches[3 * i + k] = v * float(options_.skyColour[k]);
    }
}

// The sun's light into its nearest patches, each weighed by 1 / (1.002 - cos) of its angle from the sun,
// as radiance over the patch (or over the sun's own solid angle, -5).
void SkySteps::addSun(SkyStep& s, double altitude, double azimuth) const {
    if (s.directIlluminance <= 1e-4 || brightness(options_.sunColour) <= 1e-4) return;
    int n = std::clamp(options_.sunPatches, 1, 4);
    std::vector<std::pair<double, int>> nearest(n, {-1.0, 0});  // (cosine, patch), closest first
    glm::dvec3 sun = direction(altitude, azimuth);
    for (int p = 1; p < patches_.size(); ++p) {
        glm::dvec3 d = patches_.direction(p);
        double cosine = d.x * sun.x + d.y * sun.y + d.z * sun.z;
        auto at = std::find_if(nearest.begin(), nearest.end(), [&](const auto& e) { return cosine > e.first; });
        if (at == nearest.end()) continue;
        nearest.insert(at, {cosine, p});
        nearest.pop_back();
    }
    double total = 0;
    std::vector<double> weights;
    for (const auto& e : nearest) weights.push_back(1 / (1.002 - e.first)), total += weights.back();
    for (int i = 0; i < n; ++i) {
        int p = nearest[i].second;
        float add = float(weights[i] * s.directIlluminance / (kEfficacy * total));
        add = float(add / (options_.sunSolidAngle > 0 ? options_.sunSolidAngle : double(patches_[p].solidAngle)));
        for (int k = 0; k < 3; ++k) s.patches[3 * p + k] += add * float(options_.sunColour[k]);
    }
}

std::string sunDescription(const SkyStep& step, const Rgb& sunColour, bool bright) {
    double r = kSunDiameter / 2 * kDegree;
    double radiance = bright ? step.directIlluminance / (kEfficacy * kPi * r * r) : 0;
    char text[512];
    const glm::dvec3& d = step.sunDirection;
    std::snprintf(text, sizeof text,
                  "\nvoid light solar%d\n0\n0\n3 %.3e %.3e %.3e\n\nsolar%d source sun%d\n0\n0\n4 %.6f %.6f %.6f %.4f\n",
                  step.minuteOfYear, radiance * sunColour[0], radiance * sunColour[1], radiance * sunColour[2],
                  step.minuteOfYear, step.minuteOfYear, d.x, d.y, d.z, kSunDiameter);
    return text;
}

}  // namespace brume
