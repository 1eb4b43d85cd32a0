#include "sky/cie_sky.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace brume {

namespace {

// Kittler's indicatrix of the CIE 1973 clear sky: scattering at angle gamma from the sun.
double clearIndicatrix(double gamma, double cosGamma) {
    return 0.91 + 10 * std::exp(-3 * gamma) + 0.45 * cosGamma * cosGamma;
}

// CIE 1973 clear sky gradation: luminance from the horizon up, 1 - exp(-0.32 / cos(zenith angle)).
double clearGradation(double cosZenith) { return cosZenith > 0.01 ? 1 - std::exp(-0.32 / cosZenith) : 1; }

// Radiance's intermediate sky (skybright.cal, after Matsuura's intermediate sky): eta is the point's
// zenith angle, sunZenith the sun's.
double intermediateLuminance(double gamma, double eta, double sunZenith) {
    double gradation = ((1.35 * std::sin(5.631 - 3.59 * eta) + 3.12) * std::sin(4.396 - 2.6 * sunZenith) + 6.37 - eta) / 2.326;
    return gradation * std::exp(-0.563 * gamma * ((2.629 - eta) * (1.562 - sunZenith) + 0.812));
}

// gensky's polynomial fits, in x = (altitude - 45°) / 45°, of the horizontal illuminance of the clear and
// intermediate skies over their relative zenith luminance (the integral of the distribution times cos).
double horizontalIntegralFit(CieSkyType type, double altitude) {
    static constexpr double kClear[5] = {2.766521, 0.547665, -0.369832, 0.009237, 0.059229};
    static constexpr double kIntermediate[5] = {3.5556, -2.7152, -1.3081, 1.0660, 0.60227};
    const double* c = type == CieSkyType::Intermediate ? kIntermediate : kClear;
    double x = (altitude - kPi / 4) / (kPi / 4);
    return (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
}

// gensky: the sun's radiance (W/sr/m²) through a clear atmosphere at an altitude, from 1.5e9 lm/sr/m²
// at the zenith; the intermediate sky's sun is dimmed to 15%.
double modelSolarRadiance(CieSkyType type, double sinAltitude) {
    double radiance = 1.5e9 / kSunEfficacy * (1.147 - 0.147 / std::max(sinAltitude, 0.16));
    return type == CieSkyType::Intermediate ? radiance * 0.15 : radiance;
}

double zenithRadiance(const CieSkyRequest& r, const SunAngles& sun, double horizontalFactor) {
    switch (r.zenith.unit) {
    case GivenValue::Unit::Radiance: return r.zenith.value;
    case GivenValue::Unit::Irradiance: return r.zenith.value / (horizontalFactor * kPi);
    case GivenValue::Unit::None: break;
    }
    return std::max(0.0, cieZenithLuminance(r.type, sun.altitude, r.turbidity)) / kSkyEfficacy;
}

}  // namespace

bool isOvercast(CieSkyType type) { return type == CieSkyType::Overcast || type == CieSkyType::Uniform; }

double cieRelativeLuminance(CieSkyType type, const glm::dvec3& sun, const glm::dvec3& dir) {
    double cosGamma = glm::dot(sun, dir);
    double gamma = std::acos(std::clamp(cosGamma, -1.0, 1.0));
    switch (type) {
    case CieSkyType::Clear: return clearIndicatrix(gamma, cosGamma) * clearGradation(dir.z);
    // Moon & Spencer (1942), the CIE 1955 overcast sky: three times as bright at the zenith as at the horizon.
    case CieSkyType::Overcast: return (1 + 2 * dir.z) / 3;
    case CieSkyType::Uniform: return 1;
    case CieSkyType::Intermediate:
        return intermediateLuminance(gamma, std::acos(std::clamp(dir.z, -1.0, 1.0)), std::acos(std::clamp(sun.z, -1.0, 1.0)));
    }
    return 0;
}

double cieZenithNormalisation(CieSkyType type, double altitude) {
    double sunZenith = kPi / 2 - altitude;
    // The clear sky's distribution at the zenith: indicatrix at the sun's zenith angle times the gradation
    // at the zenith, 1 - exp(-0.32) rounded to 0.274.
    if (type == CieSkyType::Clear)
        return 0.274 * (0.91 + 10 * std::exp(-3 * sunZenith) + 0.45 * std::pow(std::sin(altitude), 2));
    // The intermediate sky's distribution at the zenith, in gensky's simplified form.
    if (type == CieSkyType::Intermediate)
        return (2.739 + 0.9891 * std::sin(0.3119 + 2.6 * altitude)) * std::exp(-sunZenith * (0.4441 + 1.48 * altitude));
    return 1;
}

double cieHorizontalFactor(CieSkyType type, double altitude) {
    switch (type) {
    case CieSkyType::Uniform: return 1;
    // ∫ (1 + 2 cos θ)/3 cos θ dω over the hemisphere is 7π/9.
    case CieSkyType::Overcast: return 7.0 / 9;
    default: return horizontalIntegralFit(type, altitude) / cieZenithNormalisation(type, altitude) / kPi;
    }
}

// Zenith luminance fits as gensky uses them (Krochmann & Seidl 1974): overcast 8.6 sin(altitude) + 0.123
// kcd/m²; clear (1.376 T - 1.81) tan(altitude) + 0.38 kcd/m² for Linke turbidity T; intermediate, the mean.
double cieZenithLuminance(CieSkyType type, double altitude, double turbidity) {
    double overcast = 8.6 * std::sin(altitude) + 0.123;
    double clear = (1.376 * turbidity - 1.81) * std::tan(altitude) + 0.38;
    double kcd = isOvercast(type) ? overcast : type == CieSkyType::Intermediate ? (clear + overcast) / 2 : clear;
    return kcd * 1000;
}

CieSky makeCieSky(const CieSkyRequest& r, const SunAngles& sun) {
    CieSky sky{};
    sky.type = r.type;
    sky.sunDirection = sunDirection(sun);
    sky.zenithNormalisation = cieZenithNormalisation(r.type, sun.altitude);
    double factor = cieHorizontalFactor(r.type, sun.altitude);
    sky.zenithRadiance = zenithRadiance(r, sun, factor);
    sky.ambientLevel = sky.zenithRadiance * factor;
    double sinAltitude = sky.sunDirection.z;
    bool solarGivenAsZero = r.solar.unit != GivenValue::Unit::None && !(r.solar.value > 0);
    sky.sun = !isOvercast(r.type) && sinAltitude > 0 && !solarGivenAsZero;
    double ground = sky.ambientLevel;
    if (sky.sun) {
        sky.solarRadiance = r.solar.unit == GivenValue::Unit::Radiance     ? r.solar.value
                            : r.solar.unit == GivenValue::Unit::Irradiance ? r.solar.value / (kGenskySunSolidAngle * sinAltitude)
                                                                           : modelSolarRadiance(r.type, sinAltitude);
        // The sun's light on the ground, spread over the hemisphere (gensky's 6e-5 sr for the sun).
        ground += 6e-5 / kPi * sky.solarRadiance * sinAltitude;
    }
    sky.sun = sky.sun && r.sun;
    sky.groundRadiance = ground * r.groundReflectance;
    return sky;
}

}  // namespace brume
