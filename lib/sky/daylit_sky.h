// gendaylit's sky: a Perez all-weather sky and a sun from measured (or Perez) inputs, normalised so that
// the sky gives the input's diffuse horizontal light and the sun its direct light.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "sky/perez.h"
#include "sky/solar_position.h"

namespace brume {

// What the two input values are (gendaylit's -P, -W, -L, -G, -E).
enum class DaylitInput {
    PerezParameters,             // -P epsilon delta
    NormalIrradiance,            // -W direct normal, diffuse horizontal (W/m²)
    NormalIlluminance,           // -L direct normal, diffuse horizontal (lx)
    HorizontalIrradiance,        // -G direct horizontal, diffuse horizontal (W/m²)
    GlobalIrradiance,            // -E global horizontal (W/m²), split by Erbs et al. (1982)
};

// The unit of the radiances written (-O).
enum class DaylitOutput { VisibleRadiance = 0, SolarRadiance = 1, Luminance = 2 };

struct DaylitRequest {
    DaylitInput input = DaylitInput::PerezParameters;
    double first = 0, second = 0;  // the input values, in the order given
    DaylitOutput output = DaylitOutput::VisibleRadiance;
    bool sun = true;
    double groundReflectance = 0.2;
    double dewPoint = 10.97353115;  // °C, gendaylit's default: 2 cm of precipitable water
    int dayNumber = 0;              // day of the year; 0 with explicit sun angles, as gendaylit has it
};

// Everything gendaylit prints about a sky. `error` is its "error sky": conditions it cannot model (no
// light with the sun up, more direct light than the solar constant, ...) give a black sky instead.
struct DaylitSky {
    bool error = false;
    PerezSkyCondition condition;
    double water = 0;                  // precipitable water (cm)
    PerezCoefficients coefficients{};  // a..e
    double diffuseNormalisation = 0;   // perezlum.cal's A1
    double groundRadiance = 0;         // A2
    double solarRadiance = 0;
    std::vector<std::string> comments;  // extra "# ..." lines (-E)
};

// The sky for a sun position (altitude already limited to 87° as gendaylit limits it for non-overcast
// skies). Warnings go through warn().
DaylitSky makeDaylitSky(const DaylitRequest& request, const SunAngles& sun);

// Solid angle (sr) of gendaylit's sun: a disc 0.533° across.
double daylitSunSolidAngle();
inline constexpr double kDaylitSunDiameter = 0.533;  // degrees

}  // namespace brume
