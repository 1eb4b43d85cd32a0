// Uniform sampling of the solid angle a triangle subtends (Arvo, "Stratified sampling of spherical
// triangles", SIGGRAPH 1995): the density is 1/Ω everywhere on it, so an unoccluded uniform source
// leaves only the receiver's cosine to vary from sample to sample.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/ray.h"

namespace brume {

class SphericalTriangle {
public:
    SphericalTriangle() = default;
    // The triangle abc as seen from p.
    SphericalTriangle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c)
        : A(glm::normalize(a - p)), B(glm::normalize(b - p)), C(glm::normalize(c - p)) {
        // Van Oosterom & Strackee (1983): well conditioned even for small triangles.
        double num = std::abs(glm::dot(A, glm::cross(B, C)));
        double den = 1 + glm::dot(A, B) + glm::dot(B, C) + glm::dot(C, A);
        area_ = 2 * std::atan2(num, den);
        alpha_ = angleAt(A, B, C);
        cosC_ = glm::dot(A, B);
    }
    double solidAngle() const { return area_; }

    // The direction for (u, v) in the unit square.
    dvec3 sample(double u, double v) const {
        double areaHat = u * area_;
        double s = std::sin(areaHat - alpha_), t = std::cos(areaHat - alpha_);
        double sa = std::sin(alpha_), ca = std::cos(alpha_);
        double uu = t - ca, vv = s + sa * cosC_;
        double q = ((vv * t - uu * s) * ca - vv) / ((vv * s + uu * t) * sa);
        q = std::clamp(q, -1.0, 1.0);
        dvec3 cHat = q * A + std::sqrt(std::max(0.0, 1 - q * q)) * orthogonal(C, A);
        double z = 1 - v * (1 - glm::dot(cHat, B));
        z = std::clamp(z, -1.0, 1.0);
        return glm::normalize(z * B + std::sqrt(std::max(0.0, 1 - z * z)) * orthogonal(cHat, B));
    }

private:
    // The unit vector along the part of x orthogonal to unit y.
    static dvec3 orthogonal(const dvec3& x, const dvec3& y) {
        dvec3 d = x - glm::dot(x, y) * y;
        double len = glm::length(d);
        return len > 0 ? d / len : d;
    }
    // The spherical angle at vertex a between the arcs to b and c.
    static double angleAt(const dvec3& a, const dvec3& b, const dvec3& c) {
        dvec3 tb = orthogonal(b, a), tc = orthogonal(c, a);
        return std::acos(std::clamp(glm::dot(tb, tc), -1.0, 1.0));
    }
    dvec3 A{0}, B{0}, C{0};
    double area_ = 0, alpha_ = 0, cosC_ = 0;
};

}  // namespace brume
