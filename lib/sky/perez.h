// The Perez models as gendaylit uses them: the sky's clearness and brightness from direct and diffuse
// irradiance and the luminous efficacies of direct and diffuse light (Perez et al. 1990, Solar Energy
// 44(5)), and the all-weather sky luminance distribution (Perez, Seals & Michalsky 1993, Solar Energy 50(3)).
#pragma once

namespace brume {

inline constexpr double kSolarConstant = 1367;         // W/m², extraterrestrial
inline constexpr double kSolarConstantLux = 127500;    // lx

// The two parameters of the Perez models.
struct PerezSkyCondition {
    double clearness = 1;   // epsilon: 1 overcast ... 12 clearest
    double brightness = 0;  // delta: 0.01 dark ... 0.6 bright
};

// Kasten (1966) relative optical air mass at a solar zenith angle (degrees, at most 90).
double relativeAirMass(double zenithDegrees);
// Spencer (1971): (mean sun-earth distance / distance)² on a day of the year.
double eccentricityCorrection(int dayNumber);
// Perez et al. (1990): atmospheric precipitable water (cm) from the surface dew point (°C).
double precipitableWater(double dewPoint);

// Perez et al. (1990), eq. 1 and 2: clearness and brightness from direct normal and diffuse horizontal
// irradiance (W/m²) at a solar zenith angle (radians).
PerezSkyCondition perezSkyCondition(double directNormal, double diffuse, double zenith, int dayNumber);
// The inverse: diffuse horizontal and direct normal irradiance of a sky condition.
double perezDiffuseIrradiance(const PerezSkyCondition& sky, double zenith, int dayNumber);
double perezDirectIrradiance(const PerezSkyCondition& sky, double zenith, int dayNumber);

// Perez et al. (1990), table 4: luminous efficacy (lm/W) of diffuse horizontal and of direct normal light.
double diffuseEfficacy(const PerezSkyCondition& sky, double zenith, double water);
double directEfficacy(const PerezSkyCondition& sky, double zenith, double water);

// Coefficients a..e of the all-weather model for a sun zenith angle (radians) and sky condition.
struct PerezCoefficients {
    double a, b, c, d, e;
};
// gendaylit keeps the table's coefficients in single precision, gendaymtx in double: each program's values
// follow from its own.
enum class TablePrecision { Single, Double };
PerezCoefficients perezCoefficients(double sunZenith, const PerezSkyCondition& sky,
                                    TablePrecision precision = TablePrecision::Single);

// Perez et al. (1993), eq. 1: luminance relative to an arbitrary reference at zenith angle zeta and angle
// gamma from the sun (radians).
double perezRelativeLuminance(const PerezCoefficients& c, double zeta, double gamma);

// gendaylit's horizontal integral of the relative luminance: the sum of luminance times cos(zenith) over
// 145 points on rings 12° apart, each taken to stand for 2π/145 sr.
double perezHorizontalSum(const PerezCoefficients& c, double sunZenith);

}  // namespace brume
