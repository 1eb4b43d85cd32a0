#include "cache/surface_zones.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace brume {

SurfaceZones::SurfaceZones(const RecordShape& shape) : shape_(shape), cosMaxAngle_(std::cos(shape.maxAngle())) {}

namespace {
// Where p lies in the record's zone: 0 at its point, 1 on its edge (or beyond, or -1 far behind its plane:
// a crease). Off the plane counts like distance along the short axis. Also p's coordinates along k1, k2.
double zoneDistance(const SurfaceRecord& r, const dvec3& p, double& a, double& b) {
    dvec3 delta = p - r.point;
    double h = glm::dot(delta, r.normal);
    if (h < -0.1 * r.radius[0]) return -1;
    a = glm::dot(delta, r.axis), b = glm::dot(delta, r.axis2());
    double qa = a / r.radius[0], qb = b / r.radius[1], qh = h / r.radius[0];
    return std::sqrt(qa * qa + qb * qb + qh * qh);
}
}  // namespace

double SurfaceZones::weigh(const SurfaceRecord& r, const Receiver& at, Spectrum* value) const {
    const dvec3& n = *at.normal;
    double cosAlpha = glm::dot(n, r.normal);
    if (cosAlpha <= cosMaxAngle_) return 0;
    double a = 0, b = 0, q = zoneDistance(r, at.point, a, b);
    if (q < 0 || q >= 1) return 0;
    double alpha = std::acos(std::min(1.0, cosAlpha));
    double w = (q < 1e-6 ? 1e6 : 1 / q - 1) * (1 - alpha / shape_.maxAngle());
    if (!(w > 0)) return 0;
    if (value) {
        dvec3 tilt = n - r.normal;
        double t1 = glm::dot(tilt, r.axis), t2 = glm::dot(tilt, r.axis2());
        bool secondOrder = shape_.kind == RecordShape::Kind::Adaptive;
        const int ch = r.channels();
        *value = Spectrum(0.f, ch);
        for (int c = 0; c < ch; ++c) {
            double e = r.value(SurfaceRecord::kIrradiance, c);
            double change = r.value(SurfaceRecord::kAlongK1, c) * a + r.value(SurfaceRecord::kAlongK2, c) * b +
                            r.value(SurfaceRecord::kTiltK1, c) * t1 + r.value(SurfaceRecord::kTiltK2, c) * t2;
            if (secondOrder) change -= 0.5 * e * alpha * alpha;
            (*value)[c] = float(e + std::clamp(change, -e, e));
        }
    }
    return w;
}

// The zone is within the ellipsoid of semi-axes r0 (k1 and the normal) and r1 (k2): its box, widened for
// the float rounding of coordinates far from the origin.
ZoneBox SurfaceZones::box(const SurfaceRecord& r, const dvec3& origin) const {
    dvec3 k1 = r.axis * double(r.radius[0]), k2 = r.axis2() * double(r.radius[1]), n = r.normal * double(r.radius[0]);
    dvec3 p = r.point - origin;
    dvec3 reach = glm::sqrt(k1 * k1 + k2 * k2 + n * n) * 1.001 + 1e-6 * glm::length(p);
    ZoneBox b;
    for (int k = 0; k < 3; ++k) b.lo[k] = float(p[k] - reach[k]), b.hi[k] = float(p[k] + reach[k]);
    return b;
}

double SurfaceZones::sizeBeforeRecords() const {
    return shape_.kind == RecordShape::Kind::Classic ? shape_.accuracy * shape_.maxRadius / 4 : shape_.maxRadius / 4;
}

void SurfaceZones::shrinkToExclude(SurfaceRecord& holder, const SurfaceRecord& other) const {
    Spectrum value(0.f);
    if (weigh(holder, Receiver{other.point, other.normal}, &value) <= 0) return;
    double seen = brightness(value), actual = brightness(other.field(SurfaceRecord::kIrradiance));
    double tolerance = 2 * shape_.accuracy;
    if (std::abs(seen - actual) <= tolerance * std::max(seen, actual)) return;
    double a, b;
    float factor = float(std::max(0.5, 0.999 * zoneDistance(holder, other.point, a, b)));
    holder.radius[0] *= factor, holder.radius[1] *= factor;
}

namespace {
// The distance from the record's point to the edge of its ellipse in the tangent direction d.
double edgeToward(const SurfaceRecord& r, const dvec3& d) {
    double c = glm::dot(d, r.axis) / r.radius[0], s = glm::dot(d, r.axis2()) / r.radius[1];
    return 1 / std::sqrt(c * c + s * s);
}

// The record's gradients along and about its axes turned to `axis` (a unit tangent of the same plane).
void turnTo(SurfaceRecord& r, const dvec3& axis) {
    const dvec3 axis2 = glm::cross(r.normal, axis);
    const double c = glm::dot(r.axis, axis), s = glm::dot(r.axis2(), axis);  // k1' = c k1 + s k2
    const double c2 = glm::dot(r.axis, axis2), s2 = glm::dot(r.axis2(), axis2);
    for (auto [f1, f2] : {std::pair{SurfaceRecord::kAlongK1, SurfaceRecord::kAlongK2},
                          std::pair{SurfaceRecord::kTiltK1, SurfaceRecord::kTiltK2}}) {
        Spectrum g1 = r.field(f1), g2 = r.field(f2);
        r.setField(f1, g1 * float(c) + g2 * float(s));
        r.setField(f2, g1 * float(c2) + g2 * float(s2));
    }
    r.axis = axis;
}
}  // namespace

void SurfaceZones::shareZone(std::vector<SurfaceRecord>& records) {
    if (records.size() < 2) return;
    const SurfaceRecord& first = records.front();
    // The ellipse is checked along 64 tangent directions: between them it bulges past a neighbour's edge by
    // at most 1 - cos(π/64), 0.1 %.
    constexpr int kDirections = 64;
    double scale = 1;
    for (int i = 0; i < kDirections; ++i) {
        double phi = std::numbers::pi * i / kDirections;
        dvec3 d = first.axis * std::cos(phi) + first.axis2() * std::sin(phi);
        for (size_t k = 1; k < records.size(); ++k) scale = std::min(scale, edgeToward(records[k], d) / edgeToward(first, d));
    }
    const float radius[2] = {float(first.radius[0] * scale), float(first.radius[1] * scale)};
    const dvec3 axis = first.axis;
    for (SurfaceRecord& r : records) {
        turnTo(r, axis);
        r.radius[0] = radius[0], r.radius[1] = radius[1];
    }
}

void SurfaceZones::reconcile(SurfaceRecord& fresh, SurfaceRecord& older) const {
    shrinkToExclude(older, fresh);
    shrinkToExclude(fresh, older);
}

}  // namespace brume
