#include "contrib/reinhart_bins.h"

#include <cmath>

namespace brume {

namespace {

constexpr double kPi = 3.14159265358979323846;  // rayinit.cal's PI, DEGREE = PI/180
constexpr double kDegree = kPi / 180;

double mod(double n, double d) { return n - std::floor(n / d) * d; }                                 // b_mod
double bounded(double lo, double x, double hi) { return lo - x > 0 ? lo : (x - hi > 0 ? hi : x); }  // bound

}  // namespace

ReinhartBins::ReinhartBins(const ReinhartFrame& frame) : f_(frame), height_(90 / (7 * frame.mf + .5)) {
    const double tregenza[] = {30, 30, 24, 24, 18, 12, 6};
    int rows = int(7 * frame.mf) + 1;
    double first = 0;
    for (int r = 0; r < rows; ++r) {
        double c = r - (7 * f_.mf - .5) > 0 ? 1 : f_.mf * tregenza[int(std::floor((r + .5) / f_.mf))];
        count_.push_back(c);
        first_.push_back(first);
        first = first + c;
    }
}

double ReinhartBins::bin(const glm::dvec3& d) const {
    const glm::dvec3 &n = f_.normal, &u = f_.up;
    double up = -(d.x * n.x + d.y * n.y + d.z * n.z);
    double east = -f_.rhs * (d.x * (u.y * n.z - u.z * n.y) + d.y * (u.z * n.x - u.x * n.z) + d.z * (u.x * n.y - u.y * n.x));
    double north = d.x * u.x + d.y * u.y + d.z * u.z + up * (n.x * u.x + n.y * u.y + n.z * u.z);
    double elev = std::asin(bounded(-1, up, 1)) / kDegree;
    if (!(elev > 0)) return -1;
    double azim = mod(std::atan2(east, north) / kDegree, 360);
    int row = int(std::floor(elev / height_));
    double step = 360 / count_[row];
    double offset = .5 * step + 0;
    return first_[row] + std::floor(mod(azim + offset, 360) / step);
}

}  // namespace brume
