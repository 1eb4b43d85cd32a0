// Mappings from the unit square to directions and points with known densities.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "geometry/ray.h"

namespace brume {

// An orthonormal frame around unit vector n (Duff et al. 2017, branchless and continuous).
struct Frame {
    dvec3 s, t, n;
    explicit Frame(const dvec3& normal) : n(normal) {
        double sign = std::copysign(1.0, n.z);
        double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
        s = dvec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = dvec3(b, sign + n.y * n.y * a, -n.y);
    }
    dvec3 toWorld(const dvec3& v) const { return v.x * s + v.y * t + v.z * n; }
};

// Uniform point (x, y) on the unit disc, Shirley and Chiu's concentric map (1997): area-preserving, and
// strata of the square stay compact on the disc.
inline void concentricDisk(double u, double v, double& x, double& y) {
    double a = 2 * u - 1, b = 2 * v - 1, r, phi;
    if (a == 0 && b == 0) {
        x = y = 0;
        return;
    }
    if (a * a > b * b) r = a, phi = std::numbers::pi / 4 * (b / a);
    else r = b, phi = std::numbers::pi / 2 - std::numbers::pi / 4 * (a / b);
    x = r * std::cos(phi), y = r * std::sin(phi);
}

// Cosine-weighted direction about +z (Malley's method over the concentric disk); pdf = cosθ/π.
inline dvec3 cosineHemisphere(double u, double v) {
    double x, y;
    concentricDisk(u, v, x, y);
    return {x, y, std::sqrt(std::max(0.0, 1 - x * x - y * y))};
}

// Uniform direction in the cone of half-angle acos(cosMax) about +z; pdf = 1 / (2π(1 − cosMax)).
// The 1 − cos form keeps tiny cones (the sun: 1 − cos ≈ 1e-5) exact.
inline dvec3 uniformCone(double u, double v, double oneMinusCosMax) {
    double oneMinusCos = u * oneMinusCosMax;
    double cosT = 1 - oneMinusCos;
    double sinT = std::sqrt(std::max(0.0, oneMinusCos * (2 - oneMinusCos)));
    double phi = 2 * std::numbers::pi * v;
    return {sinT * std::cos(phi), sinT * std::sin(phi), cosT};
}

// The item a number u in [0, 1) picks from a normalised cumulative distribution `cdf` (ending at 1), with u
// made uniform again within the item's interval: one number both chooses and places, so strata stay strata.
inline size_t pickAndReuse(const std::vector<double>& cdf, double& u) {
    size_t i = std::min(size_t(std::lower_bound(cdf.begin(), cdf.end(), u) - cdf.begin()), cdf.size() - 1);
    double lo = i ? cdf[i - 1] : 0.0;
    u = cdf[i] > lo ? std::clamp((u - lo) / (cdf[i] - lo), 0.0, 1.0) : 0.0;
    return i;
}

// Uniform point on a triangle (Heitz 2019's area-preserving, low-distortion map), as barycentrics.
inline void uniformTriangle(double u, double v, double& b0, double& b1) {
    if (u < v) {
        b0 = u / 2;
        b1 = v - b0;
    } else {
        b1 = v / 2;
        b0 = u - b1;
    }
}

}  // namespace brume
