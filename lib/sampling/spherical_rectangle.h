// Uniform sampling of the solid angle a rectangle subtends (Ureña, Fajardo & King, "An Area-Preserving
// Parametrization for Spherical Rectangles", EGSR 2013). One map covers the whole rectangle, so an n×n
// grid of the unit square stays an n×n grid of equal solid angles on it; setup costs four acos, a sample
// one sin/cos pair and a few square roots, and gives the point on the rectangle, hence its distance, directly.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "geometry/ray.h"

namespace brume {

// A rectangle in space: a corner and its two edges from that corner, which must be orthogonal.
struct Rectangle {
    dvec3 corner;
    dvec3 edgeX, edgeY;
};

class SphericalRectangle {
public:
    SphericalRectangle() = default;
    // The rectangle as seen from p, which must not lie in its plane.
    SphericalRectangle(const dvec3& p, const Rectangle& r) : origin_(p) {
        double lengthX = glm::length(r.edgeX), lengthY = glm::length(r.edgeY);
        x_ = r.edgeX / lengthX, y_ = r.edgeY / lengthY, z_ = glm::cross(x_, y_);
        dvec3 d = r.corner - p;
        x0_ = glm::dot(d, x_), y0_ = glm::dot(d, y_), z0_ = glm::dot(d, z_);
        if (z0_ > 0) z0_ = -z0_, z_ = -z_;  // the frame's z points from the rectangle toward p
        x1_ = x0_ + lengthX, y1_ = y0_ + lengthY;
        // Unit normals of the planes through p and each edge, written out in the rectangle's frame; the
        // rectangle's interior angles are the angles between consecutive ones.
        dvec3 n0 = dvec3(0, z0_, -y0_) / std::sqrt(z0_ * z0_ + y0_ * y0_);
        dvec3 n1 = dvec3(-z0_, 0, x1_) / std::sqrt(z0_ * z0_ + x1_ * x1_);
        dvec3 n2 = dvec3(0, -z0_, y1_) / std::sqrt(z0_ * z0_ + y1_ * y1_);
        dvec3 n3 = dvec3(z0_, 0, -x0_) / std::sqrt(z0_ * z0_ + x0_ * x0_);
        double g0 = std::acos(std::clamp(-glm::dot(n0, n1), -1.0, 1.0));
        double g1 = std::acos(std::clamp(-glm::dot(n1, n2), -1.0, 1.0));
        double g2 = std::acos(std::clamp(-glm::dot(n2, n3), -1.0, 1.0));
        double g3 = std::acos(std::clamp(-glm::dot(n3, n0), -1.0, 1.0));
        b0_ = n0.z, b1_ = n2.z;
        k_ = 2 * std::numbers::pi - g2 - g3;
        solidAngle_ = std::max(0.0, g0 + g1 - k_);
    }
    double solidAngle() const { return solidAngle_; }

    // The point of the rectangle for (u, v) in the unit square; its direction from p is uniform in solid angle.
    dvec3 sample(double u, double v) const {
        double au = u * solidAngle_ + k_;
        double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
        double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0, 1.0);
        double xu = std::clamp(-(cu * z0_) / std::sqrt(std::max(0.0, 1 - cu * cu)), x0_, x1_);
        double d2 = xu * xu + z0_ * z0_, d = std::sqrt(d2);
        double h0 = y0_ / std::sqrt(d2 + y0_ * y0_), h1 = y1_ / std::sqrt(d2 + y1_ * y1_);
        double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
        double yv = hv2 < 1 - 1e-12 ? std::clamp(hv * d / std::sqrt(1 - hv2), y0_, y1_) : y1_;
        return origin_ + xu * x_ + yv * y_ + z0_ * z_;
    }

private:
    dvec3 origin_{0}, x_{0}, y_{0}, z_{0};
    double x0_ = 0, y0_ = 0, z0_ = 0, x1_ = 0, y1_ = 0;
    double b0_ = 0, b1_ = 0, k_ = 0, solidAngle_ = 0;
};

}  // namespace brume
