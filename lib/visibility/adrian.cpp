#include "visibility/adrian.h"

#include <algorithm>
#include <cmath>

namespace brume {

namespace {

// Adrian's square roots of the Ricco (Φ) and Weber (L) functions in the photopic, mesopic and scotopic ranges.
void adrianFunctions(double lb, double& rootPhi, double& rootL) {
    double x = std::log10(lb);
    if (lb >= 0.6) {
        rootPhi = std::log10(4.1925 * std::pow(lb, 0.1556)) + 0.1684 * std::pow(lb, 0.5867);
        rootL = 0.05946 * std::pow(lb, 0.466);
    } else if (lb > 0.00418) {
        rootPhi = std::pow(10.0, -0.072 + 0.3372 * x + 0.0866 * x * x);
        rootL = std::pow(10.0, -1.256 + 0.319 * x);
    } else {
        rootPhi = std::pow(10.0, 0.028 + 0.173 * x);
        rootL = std::pow(10.0, -0.891 + 0.5275 * x + 0.0227 * x * x);
    }
}

}  // namespace

double adrianBasicThreshold(double lb, double arcmin) {
    double rootPhi, rootL;
    adrianFunctions(lb, rootPhi, rootL);
    double r = rootPhi / arcmin + rootL;
    return 2.6 * r * r;
}

double adrianTimeConstant(double lb, double arcmin) {
    double x = std::log10(arcmin) + 0.523, y = std::log10(lb) + 6;
    double aAlpha = 0.36 - 0.0972 * x * x / (x * x - 2.513 * x + 2.7895);
    double aL = 0.355 - 0.1217 * y * y / (y * y - 10.4 * y + 52.28);
    return std::sqrt(aAlpha * aAlpha + aL * aL) / 2.1;
}

double adrianAgeFactor(double age) {
    age = std::clamp(age, 23.0, 75.0);
    return age <= 64 ? (age - 19) * (age - 19) / 2160 + 0.99 : (age - 56.6) * (age - 56.6) / 116.3 + 1.43;
}

double adrianPolarityFactor(double lb, double arcmin) {
    double x = std::log10(lb);
    if (x <= -2.4) return 0.5;  // RP-8's value in the dark, where the fit below leaves its range
    double c = lb >= 0.1 ? 0.125 : 0.075;
    double m = std::pow(10.0, -std::pow(10.0, -(c * (x + 1) * (x + 1) + 0.0245)));
    double beta = 0.6 * std::pow(lb, -0.1488);
    double atTwoSeconds = adrianBasicThreshold(lb, arcmin) * (adrianTimeConstant(lb, arcmin) + 2) / 2;
    return 1 - m * std::pow(arcmin, -beta) / (2.4 * atTwoSeconds);
}

double adrianThreshold(double lb, double arcmin, bool positive, const AdrianObserver& o) {
    lb = std::max(lb, kDarkest);
    arcmin = std::max(arcmin, 1e-3);
    double t = std::max(o.seconds, 1e-3);
    double threshold = adrianBasicThreshold(lb, arcmin) * (adrianTimeConstant(lb, arcmin) + t) / t * adrianAgeFactor(o.age);
    return positive ? threshold : threshold * adrianPolarityFactor(lb, arcmin);
}

}  // namespace brume
