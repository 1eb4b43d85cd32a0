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
// x = x1 + x2 Z + delta (x3 + x4 Z). Kept in single precision as gendaylit keeps them: the coefficients it
// prints with six decimals show the difference. Float literals: GCC with -frounding-math (CGAL's flag)
// miscompiles double literals narrowed to float in a constant array.
constexpr float kLuminanceCoefficients[8][5][4] = {
    {{1.3525f, -0.2576f, -0.2690f, -1.4366f}, {-0.7670f, 0.0007f, 1.2734f, -0.1233f}, {2.8000f, 0.6004f, 1.2375f, 1.000f}, {1.8734f, 0.6297f, 0.9738f, 0.2809f}, {0.0356f, -0.1246f, -0.5718f, 0.9938f}},
    {{-1.2219f, -0.7730f, 1.4148f, 1.1016f}, {-0.2054f, 0.0367f, -3.9128f, 0.9156f}, {6.9750f, 0.1774f, 6.4477f, -0.1239f}, {-1.5798f, -0.5081f, -1.7812f, 0.1080f}, {0.2624f, 0.0672f, -0.2190f, -0.4285f}},
    {{-1.1000f, -0.2515f, 0.8952f, 0.0156f}, {0.2782f, -0.1812f, -4.5000f, 1.1766f}, {24.7219f, -13.0812f, -37.7000f, 34.8438f}, {-5.0000f, 1.5218f, 3.9229f, -2.6204f}, {-0.0156f, 0.1597f, 0.4199f, -0.5562f}},
    {{-0.5484f, -0.6654f, -0.2672f, 0.7117f}, {0.7234f, -0.6219f, -5.6812f, 2.6297f}, {33.3389f, -18.3000f, -62.2500f, 52.0781f}, {-3.5000f, 0.0016f, 1.1477f, 0.1062f}, {0.4659f, -0.3296f, -0.0876f, -0.0329f}},
    {{-0.6000f, -0.3566f, -2.5000f, 2.3250f}, {0.2937f, 0.0496f, -5.6812f, 1.8415f}, {21.0000f, -4.7656f, -21.5906f, 7.2492f}, {-3.5000f, -0.1554f, 1.4062f, 0.3988f}, {0.0032f, 0.0766f, -0.0656f, -0.1294f}},
    {{-1.0156f, -0.3670f, 1.0078f, 1.4051f}, {0.2875f, -0.5328f, -3.8500f, 3.3750f}, {14.0000f, -0.9999f, -7.1406f, 7.5469f}, {-3.4000f, -0.1078f, -1.0750f, 1.5702f}, {-0.0672f, 0.4016f, 0.3017f, -0.4844f}},
    {{-1.0000f, 0.0211f, 0.5025f, -0.5119f}, {-0.3000f, 0.1922f, 0.7023f, -1.6317f}, {19.0000f, -5.0000f, 1.2438f, -1.9094f}, {-4.0000f, 0.0250f, 0.3844f, 0.2656f}, {1.0468f, -0.3788f, -2.4517f, 1.4656f}},
    {{-1.0500f, 0.0289f, 0.4260f, 0.3590f}, {-0.3250f, 0.1156f, 0.7781f, 0.0025f}, {31.0625f, -14.5000f, -46.1148f, 55.3750f}, {-7.2312f, 0.4050f, 13.3500f, 0.6234f}, {1.5000f, -0.6426f, 1.8564f, 0.5636f}},
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
PerezCoefficients perezCoefficients(double z, const PerezSkyCondition& sky) {
    double eps = sky.clearness, delta = sky.brightness;
    if (eps > 1.065 && eps < 2.8) delta = std::max(delta, 0.2);
    int bin = clearnessBin(eps);
    const auto& x = kLuminanceCoefficients[bin];
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
