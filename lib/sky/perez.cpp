#include "sky/perez.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "sky/solar_position.h"

namespace brume {

namespace {

// The eight clearness bins of both Perez models: lower bounds of bins 1..7 (bin 0 starts at 1).
int clearnessBin(double clearness) {
    static constexpr double kLowerBounds[] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};
    return int(std::upper_bound(std::begin(kLowerBounds), std::end(kLowerBounds), clearness) - kLowerBounds);
}

// Perez et al. (1993), table 1: for each clearness bin, for a..e, the four coefficients of
// x = x1 + x2 Z + delta (x3 + x4 Z). gendaylit rounds them to single precision (the coefficients it prints
// with six decimals show it), at run time: GCC with -frounding-math (CGAL's flag) miscompiles double
// literals narrowed to float in a constant array.
constexpr double kLuminanceCoefficients[8][5][4] = {
    {{1.3525, -0.2576, -0.2690, -1.4366}, {-0.7670, 0.0007, 1.2734, -0.1233}, {2.8000, 0.6004, 1.2375, 1.000}, {1.8734, 0.6297, 0.9738, 0.2809}, {0.0356, -0.1246, -0.5718, 0.9938}},
    {{-1.2219, -0.7730, 1.4148, 1.1016}, {-0.2054, 0.0367, -3.9128, 0.9156}, {6.9750, 0.1774, 6.4477, -0.1239}, {-1.5798, -0.5081, -1.7812, 0.1080}, {0.2624, 0.0672, -0.2190, -0.4285}},
    {{-1.1000, -0.2515, 0.8952, 0.0156}, {0.2782, -0.1812, -4.5000, 1.1766}, {24.7219, -13.0812, -37.7000, 34.8438}, {-5.0000, 1.5218, 3.9229, -2.6204}, {-0.0156, 0.1597, 0.4199, -0.5562}},
    {{-0.5484, -0.6654, -0.2672, 0.7117}, {0.7234, -0.6219, -5.6812, 2.6297}, {33.3389, -18.3000, -62.2500, 52.0781}, {-3.5000, 0.0016, 1.1477, 0.1062}, {0.4659, -0.3296, -0.0876, -0.0329}},
    {{-0.6000, -0.3566, -2.5000, 2.3250}, {0.2937, 0.0496, -5.6812, 1.8415}, {21.0000, -4.7656, -21.5906, 7.2492}, {-3.5000, -0.1554, 1.4062, 0.3988}, {0.0032, 0.0766, -0.0656, -0.1294}},
    {{-1.0156, -0.3670, 1.0078, 1.4051}, {0.2875, -0.5328, -3.8500, 3.3750}, {14.0000, -0.9999, -7.1406, 7.5469}, {-3.4000, -0.1078, -1.0750, 1.5702}, {-0.0672, 0.4016, 0.3017, -0.4844}},
    {{-1.0000, 0.0211, 0.5025, -0.5119}, {-0.3000, 0.1922, 0.7023, -1.6317}, {19.0000, -5.0000, 1.2438, -1.9094}, {-4.0000, 0.0250, 0.3844, 0.2656}, {1.0468, -0.3788, -2.4517, 1.4656}},
    {{-1.0500, 0.0289, 0.4260, 0.3590}, {-0.3250, 0.1156, 0.7781, 0.0025}, {31.0625, -14.5000, -46.1148, 55.3750}, {-7.2312, 0.4050, 13.3500, 0.6234}, {1.5000, -0.6426, 1.8564, 0.5636}},
};

// Perez et al. (1990), table 4: a, b, c, d per clearness bin.
constexpr double kDiffuseEfficacy[8][4] = {
    {97.24, -0.46, 12.00, -8.91},     {107.22, 1.15, 0.59, -3.95},    {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90},   {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03},   {152.23, 0.35, -45.27, -7.98}};
constexpr double kDirectEfficacy[8][4] = {
    {57.20, -4.55, -2.98, 117.12},  {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56},  {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44},  {101.18, 1.58, -1.10, -8.29}};

// Perez et al. (1990), eq. 1: the zenith-angle term 1.041 Z³ of the clearness.
double clearnessZenithTerm(double zenith) { return 1.041 * zenith * zenith * zenith; }

// Extraterrestrial irradiance over air mass: what the brightness is measured against.
double brightnessScale(double zenith, int dayNumber) {
    return kSolarConstant * eccentricityCorrection(dayNumber) / relativeAirMass(zenith / kDegree);
}

}  // namespace

// Kasten (1966): m = 1 / (cos Z + 0.15 (93.885 - Z)^-1.253), Z in degrees.
double relativeAirMass(double z) {
    return 1 / (std::cos(z * kDegree) + 0.15 * std::exp(std::log(93.885 - z) * -1.253));
}

// Spencer (1971), Fourier series in the day angle.
double eccentricityCorrection(int dayNumber) {
    double g = 2 * kPi * (dayNumber - 1) / 365;
    return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
           0.000077 * std::sin(2 * g);
}

double precipitableWater(double dewPoint) { return std::exp(0.07 * dewPoint - 0.075); }

PerezSkyCondition perezSkyCondition(double directNormal, double diffuse, double zenith, int dayNumber) {
    double k = clearnessZenithTerm(zenith);
    return {((diffuse + directNormal) / diffuse + k) / (1 + k), diffuse / brightnessScale(zenith, dayNumber)};
}

double perezDiffuseIrradiance(const PerezSkyCondition& sky, double zenith, int dayNumber) {
    return sky.brightness * brightnessScale(zenith, dayNumber);
}

double perezDirectIrradiance(const PerezSkyCondition& sky, double zenith, int dayNumber) {
    return perezDiffuseIrradiance(sky, zenith, dayNumber) * (sky.clearness - 1) * (1 + clearnessZenithTerm(zenith));
}

// Perez et al. (1990), eq. 7: a + b W + c cos Z + d ln(delta).
double diffuseEfficacy(const PerezSkyCondition& sky, double zenith, double water) {
    const double* k = kDiffuseEfficacy[clearnessBin(sky.clearness)];
    return k[0] + k[1] * water + k[2] * std::cos(zenith) + k[3] * std::log(sky.brightness);
}

// Perez et al. (1990), eq. 8: a + b W + c exp(5.73 Z - 5) + d delta, never negative.
double directEfficacy(const PerezSkyCondition& sky, double zenith, double water) {
    const double* k = kDirectEfficacy[clearnessBin(sky.clearness)];
    return std::max(0.0, k[0] + k[1] * water + k[2] * std::exp(5.73 * zenith - 5) + k[3] * sky.brightness);
}

// Perez et al. (1993), eq. 6 and table 1; in the first bin c and d follow eq. 7 and 8. gendaylit raises
// delta to 0.2 in the bins between 1.065 and 2.8.
PerezCoefficients perezCoefficients(double z, const PerezSkyCondition& sky, TablePrecision precision) {
    double eps = sky.clearness, delta = sky.brightness;
    if (eps > 1.065 && eps < 2.8) delta = std::max(delta, 0.2);
    int bin = clearnessBin(eps);
    double x[5][4];
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = kLuminanceCoefficients[bin][i][j];
            x[i][j] = precision == TablePrecision::Single ? double(float(v)) : v;
        }
    auto linear = [&](int i) { return x[i][0] + x[i][1] * z + delta * (x[i][2] + x[i][3] * z); };
    if (bin > 0) return {linear(0), linear(1), linear(2), linear(3), linear(4)};
    return {linear(0), linear(1), std::exp(std::pow(delta * (x[2][0] + x[2][1] * z), x[2][2])) - x[2][3],
            -std::exp(delta * (x[3][0] + x[3][1] * z)) + x[3][2] + delta * x[3][3], linear(4)};
}

double perezRelativeLuminance(const PerezCoefficients& c, double zeta, double gamma) {
    double cosGamma = std::cos(gamma);
    return (1 + c.a * std::exp(c.b / std::cos(zeta))) * (1 + c.c * std::exp(c.d * gamma) + c.e * cosGamma * cosGamma);
}

double perezHorizontalSum(const PerezCoefficients& c, double sunZenith) {
    // Rings at zenith angles 84°, 72°, ... 12° with 30, 30, 24, 24, 18, 12, 6 points, and the zenith.
    static constexpr int kRingPoints[8] = {30, 30, 24, 24, 18, 12, 6, 1};
    double sum = 0;
    for (int ring = 0; ring < 8; ++ring) {
        double theta = (84 - 12 * ring) * kDegree;
        for (int k = 0; k < kRingPoints[ring]; ++k) {
            double phi = 360.0 / kRingPoints[ring] * k * kDegree;
            double cosGamma = std::cos(sunZenith) * std::cos(theta) + std::sin(sunZenith) * std::sin(theta) * std::cos(phi);
            double gamma = cosGamma > 1 ? 0 : std::acos(cosGamma);
            // gendaylit keeps these luminances in single precision.
            sum += float(perezRelativeLuminance(c, theta, gamma)) * std::cos(theta);
        }
    }
    return sum * (2 * kPi / 145);
}

}  // namespace brume
