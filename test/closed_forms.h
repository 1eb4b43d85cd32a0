// Closed-form irradiance of simple sources, which the analytic tests check against.
#pragma once
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "geometry/ray.h"

namespace brume::test {

// A sphere source seen whole above the sensor's horizon gives E = π L (r/d)² cos β, exactly.
inline double sphereIrradiance(double L, double r, const dvec3& center, const dvec3& p, const dvec3& n) {
    dvec3 toC = center - p;
    double d = glm::length(toC);
    return std::numbers::pi * L * (r / d) * (r / d) * glm::dot(glm::normalize(n), toC / d);
}

// Configuration factor from a point to a parallel rectangle w × l at height h, the point under a corner
// (e.g. Howell's catalogue, C-11).
inline double cornerFormFactor(double w, double l, double h) {
    double a = w / h, b = l / h;
    double sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
    return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2 * std::numbers::pi);
}

}  // namespace brume::test
