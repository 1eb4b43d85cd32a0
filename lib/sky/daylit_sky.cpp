#include "sky/daylit_sky.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sky/cie_sky.h"
#include "util/error.h"

namespace brume {

namespace {

// Thrown by the checks below: gendaylit gives up on the conditions and prints a black "error sky".
struct ErrorSky {};

[[noreturn]] void errorSky(const std::string& why) {
    warn(why + ", printing error sky");
    throw ErrorSky{};
}

// Direct normal and diffuse horizontal light, in W/m² or in lx.
struct Light {
    double direct = 0, diffuse = 0;
};

// What the request's inputs become: the sky's condition, its irradiance and (unless -O 1) illuminance.
struct Inputs {
    PerezSkyCondition condition;
    Light irradiance, illuminance;
};

// gendaylit keeps epsilon in [1, 12.01) and delta in [0.01, 0.6], the range of the models' data.
PerezSkyCondition limited(PerezSkyCondition c) {
    if (std::isnan(c.clearness)) errorSky("sky clearness undefined (no diffuse light)");
    c.clearness = c.clearness < 1 ? 1 : c.clearness > 12.01 ? 12.009 : c.clearness;
    c.brightness = std::clamp(c.brightness, 0.01, 0.6);
    return c;
}

// Negative values count as zero; no light at all with the sun up, or more direct light than outside the
// atmosphere, gives the error sky.
void check(Light& light, double altitude, double solarConstant, const std::string& quantity) {
    if (light.direct < 0) warn("direct " + quantity + " < 0, using 0"), light.direct = 0;
    if (light.diffuse < 0) warn("diffuse " + quantity + " < 0, using 0"), light.diffuse = 0;
    if (light.direct + light.diffuse == 0 && altitude > 0) errorSky("zero " + quantity + " at sun altitude > 0");
    if (light.direct > solarConstant) errorSky("direct " + quantity + " exceeds solar constant");
}

struct Sun {
    double altitude, zenith;  // radians; the zenith angle no more than 90° (the air mass is finite)
    int dayNumber;
    double water;
};

void addIlluminance(Inputs& in, const Sun& sun, DaylitOutput output) {
    if (output == DaylitOutput::SolarRadiance) return;
    in.illuminance = {in.irradiance.direct * directEfficacy(in.condition, sun.zenith, sun.water),
                      in.irradiance.diffuse * diffuseEfficacy(in.condition, sun.zenith, sun.water)};
    check(in.illuminance, sun.altitude, kSolarConstantLux, "illuminance");
}

// -W, -G and -E end here: the sky condition from direct normal and diffuse irradiance.
Inputs fromIrradiance(Light irradiance, const Sun& sun, DaylitOutput output) {
    check(irradiance, sun.altitude, kSolarConstant, "irradiance");
    Inputs in{limited(perezSkyCondition(irradiance.direct, irradiance.diffuse, sun.zenith, sun.dayNumber)), irradiance, {}};
    addIlluminance(in, sun, output);
    return in;
}

Inputs fromPerezParameters(PerezSkyCondition given, const Sun& sun, DaylitOutput output) {
    PerezSkyCondition c = limited(given);
    Inputs in{c, {perezDirectIrradiance(c, sun.zenith, sun.dayNumber), perezDiffuseIrradiance(c, sun.zenith, sun.dayNumber)}, {}};
    check(in.irradiance, sun.altitude, kSolarConstant, "irradiance");
    addIlluminance(in, sun, output);
    return in;
}

// -L: the irradiance whose Perez efficacies give the illuminance, found by fixed-point iteration from
// the ratio of the solar constants. gendaylit's stopping test never holds, so it always makes 9 steps.
Inputs fromIlluminance(Light illuminance, const Sun& sun) {
    check(illuminance, sun.altitude, kSolarConstantLux, "illuminance");
    auto condition = [&](const Light& e) { return limited(perezSkyCondition(e.direct, e.diffuse, sun.zenith, sun.dayNumber)); };
    double ratio = kSolarConstant / kSolarConstantLux;
    Inputs in{{}, {illuminance.direct * ratio, illuminance.diffuse * ratio}, illuminance};
    in.condition = condition(in.irradiance);
    for (int step = 0; step < 9; ++step) {
        in.irradiance.diffuse = illuminance.diffuse / diffuseEfficacy(in.condition, sun.zenith, sun.water);
        double efficacy = directEfficacy(in.condition, sun.zenith, sun.water);
        in.irradiance.direct = efficacy < 0.1 ? 0 : illuminance.direct / efficacy;
        in.condition = condition(in.irradiance);
    }
    return in;
}

// Erbs, Klein & Duffie (1982), Solar Energy 28(4): the diffuse fraction of global horizontal irradiance
// from the clearness index kt.
double erbsDiffuseFraction(double kt) {
    if (kt <= 0.22) return 1 - 0.09 * kt;
    if (kt <= 0.8) return 0.9511 - 0.1604 * kt + 4.388 * std::pow(kt, 2) - 16.638 * std::pow(kt, 3) + 12.336 * std::pow(kt, 4);
    return kt < 1 ? 0.165 : 0;
}

// -E: global horizontal irradiance split into direct and diffuse; gendaylit notes the split in comments.
Light splitGlobal(double global, const Sun& sun, std::vector<std::string>& comments) {
    if (sun.altitude <= 0) {
        if (global > 50) warn("global irradiance higher than 50 W/m^2 while the sun altitude is lower than zero");
        return {};
    }
    double extraterrestrial = kSolarConstant * eccentricityCorrection(sun.dayNumber) * std::sin(sun.altitude);
    if (global > extraterrestrial) {
        warn("global irradiance is higher than the time-dependent solar constant s0");
        global = extraterrestrial * 0.999;
    }
    double kt = global / extraterrestrial;
    double diffuse = global * erbsDiffuseFraction(kt);
    char line[160];
    std::snprintf(line, sizeof line, "# erbs_s0, erbs_kt, irr_dir_h, irr_diff: %.3f %.3f %.3f %.3f", extraterrestrial, kt,
                  global - diffuse, diffuse);
    comments = {line, "# WARNING: the -E option is only recommended for a rough estimation!"};
    return {(global - diffuse) / std::sin(sun.altitude), diffuse};
}

Inputs inputs(const DaylitRequest& r, const Sun& sun, std::vector<std::string>& comments) {
    switch (r.input) {
    case DaylitInput::PerezParameters: return fromPerezParameters({r.first, r.second}, sun, r.output);
    case DaylitInput::NormalIrradiance: return fromIrradiance({r.first, r.second}, sun, r.output);
    case DaylitInput::NormalIlluminance: return fromIlluminance({r.first, r.second}, sun);
    case DaylitInput::HorizontalIrradiance:
        if (sun.altitude > 0) return fromIrradiance({r.first / std::sin(sun.altitude), r.second}, sun, r.output);
        warn("sun altitude < 0, proceed with irradiance values of zero");
        return fromIrradiance({}, sun, r.output);
    case DaylitInput::GlobalIrradiance: return fromIrradiance(splitGlobal(r.first, sun, comments), sun, r.output);
    }
    return {};
}

// The CIE sky whose horizontal factor gendaylit uses for the ground: overcast at epsilon 1, clear from 6.
CieSkyType cieTypeOf(double clearness) {
    return clearness == 1 ? CieSkyType::Overcast : clearness >= 6 ? CieSkyType::Clear : CieSkyType::Intermediate;
}

}  // namespace

// A disc of 0.533°: 2π (1 - cos(half the diameter)).
double daylitSunSolidAngle() { return 2 * kPi * (1 - std::cos(kDaylitSunDiameter / 2 * kDegree)); }

DaylitSky makeDaylitSky(const DaylitRequest& r, const SunAngles& angles) {
    DaylitSky sky;
    double zenithDegrees = 90 - angles.altitude / kDegree;
    if (zenithDegrees > 90) warn("air mass has reached the maximal value"), zenithDegrees = 90;
    Sun sun{angles.altitude, zenithDegrees * kDegree, r.dayNumber, precipitableWater(r.dewPoint)};
    sky.water = sun.water;
    try {
        Inputs in = inputs(r, sun, sky.comments);
        sky.condition = in.condition;
        sky.coefficients = perezCoefficients(sun.zenith, in.condition);
        double sum = perezHorizontalSum(sky.coefficients, sun.zenith);
        bool watts = r.output == DaylitOutput::SolarRadiance;
        double efficacy = r.output == DaylitOutput::VisibleRadiance ? kWhiteEfficacy : 1;
        const Light& light = watts ? in.irradiance : in.illuminance;
        sky.diffuseNormalisation = light.diffuse / sum / efficacy;
        sky.solarRadiance = light.direct / daylitSunSolidAngle() / efficacy;
        double zenith = perezRelativeLuminance(sky.coefficients, 0, sun.zenith) * sky.diffuseNormalisation;
        double ground = zenith * cieHorizontalFactor(cieTypeOf(in.condition.clearness), angles.altitude);
        // The sun's light on the ground, with gendaylit's 6.8e-5 sr for the sun.
        if (r.sun && in.condition.clearness > 1) ground += 6.8e-5 / kPi * sky.solarRadiance * std::sin(angles.altitude);
        sky.groundRadiance = ground * r.groundReflectance;
        // The model is fitted for a luminance that falls off toward the horizon (b < 0).
        if (sky.coefficients.b > 0) errorSky("positive Perez parameter B (= " + std::to_string(sky.coefficients.b) + ")");
    } catch (const ErrorSky&) {
        sky.error = true;
    }
    return sky;
}

}  // namespace brume
