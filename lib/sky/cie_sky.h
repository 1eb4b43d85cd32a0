// The CIE skies of Radiance's gensky: clear (CIE 1973), intermediate, overcast (Moon & Spencer, CIE 1955)
// and uniform; their luminance distributions, zenith luminance and horizontal illuminance, and the sun.
// Radiances are in W/sr/m² as Radiance uses them (luminance divided by a luminous efficacy).
#pragma once
#include <glm/vec3.hpp>

#include "sky/solar_position.h"

namespace brume {

// The numbers are the sky type skybright.cal takes as its first argument.
enum class CieSkyType { Clear = 1, Overcast = 2, Uniform = 3, Intermediate = 4 };

// Luminous efficacies (lm/W) by which Radiance turns luminance into its radiance.
inline constexpr double kSkyEfficacy = 203;    // skylight, taken as CIE D65
inline constexpr double kSunEfficacy = 208;    // direct sun, CIE illuminant B
inline constexpr double kWhiteEfficacy = 179;  // equal-energy white, 380-780 nm

// Solid angle (sr) gensky gives the sun when it converts irradiance, and the one for the ground's share.
inline constexpr double kGenskySunSolidAngle = 5.98e-5;

// True for the skies without a sun (overcast and uniform).
bool isOvercast(CieSkyType type);

// The sky's luminance in direction `dir` relative to its zenith normalisation, where `sun` is the unit
// vector toward the sun: what skybright.cal computes above the horizon before the ground is blended in.
double cieRelativeLuminance(CieSkyType type, const glm::dvec3& sun, const glm::dvec3& dir);

// The relative luminance of the clear and intermediate skies at the zenith, as gensky approximates it
// (skybright.cal's fourth argument); 1 for the others.
double cieZenithNormalisation(CieSkyType type, double sunAltitude);

// Horizontal diffuse illuminance over zenith luminance, divided by π: the factor gensky multiplies the
// zenith radiance by to get the sky's "ground ambient level".
double cieHorizontalFactor(CieSkyType type, double sunAltitude);

// Zenith luminance (cd/m²) of the sky at a sun altitude and, for the clear skies, a Linke turbidity.
double cieZenithLuminance(CieSkyType type, double sunAltitude, double turbidity);

// A value gensky may be given instead of computing it: as a radiance or as an irradiance.
struct GivenValue {
    enum class Unit { None, Radiance, Irradiance } unit = Unit::None;
    double value = 0;
};

struct CieSkyRequest {
    CieSkyType type = CieSkyType::Clear;
    bool sun = true;
    double turbidity = 2.45;
    double groundReflectance = 0.2;
    GivenValue zenith;  // -b / -B
    GivenValue solar;   // -r / -R
};

// Everything gensky prints about a sky.
struct CieSky {
    CieSkyType type;
    glm::dvec3 sunDirection;
    double zenithRadiance;       // W/sr/m²
    double ambientLevel;         // sky's horizontal irradiance / π, the suggested -av
    double groundRadiance;       // below the horizon: reflected sky and sun
    double zenithNormalisation;  // skybright.cal's A4 (clear and intermediate)
    double solarRadiance;        // W/sr/m², when `sun`
    bool sun;
};

// gensky's sky for a sun position (the altitude already limited as gensky limits it).
CieSky makeCieSky(const CieSkyRequest& request, const SunAngles& sun);

}  // namespace brume
