#include "geometry/shapes.h"

#include <cmath>

namespace brume {

bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
    if (a == 0) {
        if (b == 0) return false;
        t0 = t1 = -c / b;
        return true;
    }
    double disc = b * b - 4 * a * c;
    if (disc < 0) return false;
    // Numerical Recipes' form: no subtraction of nearly equal numbers.
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    t0 = q / a;
    t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

namespace {

// The nearer acceptable root: when the ray starts on this very surface, the root nearest zero is the
// origin itself and is dropped, whatever its sign rounding gave it.
template <class Accept>
std::optional<double> pickRoot(double t0, double t1, const Ray& ray, bool leavingThis, Accept accept) {
    if (leavingThis) {
        double other = std::abs(t0) < std::abs(t1) ? t1 : t0;
        if (other > ray.tmin && other < ray.tmax && accept(other)) return other;
        return std::nullopt;
    }
    for (double t : {t0, t1})
        if (t > ray.tmin && t < ray.tmax && accept(t)) return t;
    return std::nullopt;
}

}  // namespace

std::optional<ShapeHit> Sphere::intersect(const Ray& ray, bool leavingThis) const {
    dvec3 w = ray.org - center;
    double t0, t1;
    if (!solveQuadratic(glm::dot(ray.dir, ray.dir), 2 * glm::dot(w, ray.dir), glm::dot(w, w) - radius * radius, t0, t1))
        return std::nullopt;
    auto t = pickRoot(t0, t1, ray, leavingThis, [](double) { return true; });
    if (!t) return std::nullopt;
    dvec3 n = (ray.at(*t) - center) / radius;
    return ShapeHit{*t, inward ? -n : n};
}

std::optional<ShapeHit> Cone::intersect(const Ray& ray, bool leavingThis) const {
    dvec3 axis = top - base;
    double h = glm::length(axis);
    dvec3 a = axis / h;
    double k = (topRadius - baseRadius) / h;  // radius change per unit height
    dvec3 w = ray.org - base;
    double zw = glm::dot(w, a), dz = glm::dot(ray.dir, a);
    double rw = baseRadius + k * zw;
    // |w + tD|² − z(t)² = r(z(t))², with z(t) = zw + t·dz and r(z) = r0 + k·z.
    double qa = glm::dot(ray.dir, ray.dir) - dz * dz * (1 + k * k);
    double qb = 2 * (glm::dot(w, ray.dir) - zw * dz - k * dz * rw);
    double qc = glm::dot(w, w) - zw * zw - rw * rw;
    double t0, t1;
    if (!solveQuadratic(qa, qb, qc, t0, t1)) return std::nullopt;
    auto within = [&](double t) {
        double z = zw + t * dz;
        return z >= 0 && z <= h;
    };
    auto t = pickRoot(t0, t1, ray, leavingThis, within);
    if (!t) return std::nullopt;
    dvec3 v = ray.at(*t) - base;
    double z = glm::dot(v, a);
    dvec3 n = glm::normalize((v - z * a) - (baseRadius + k * z) * k * a);
    return ShapeHit{*t, inward ? -n : n};
}

std::optional<ShapeHit> Ring::intersect(const Ray& ray) const {
    double denom = glm::dot(normal, ray.dir);
    if (denom == 0) return std::nullopt;
    double t = glm::dot(normal, center - ray.org) / denom;
    if (!(t > ray.tmin && t < ray.tmax)) return std::nullopt;
    dvec3 d = ray.at(t) - center;
    double r2 = glm::dot(d, d);
    if (r2 < innerRadius * innerRadius || r2 > outerRadius * outerRadius) return std::nullopt;
    return ShapeHit{t, normal};
}

}  // namespace brume
