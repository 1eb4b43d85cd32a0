#include "cache/volume_zones.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace brume {

namespace {

// What the gradient of coefficient k in channel c adds over the offset delta from the record's point.
double change(const VolumeRecord& r, const dvec3& delta, int k, int c) {
    return r.value(1, k, c) * delta.x + r.value(2, k, c) * delta.y + r.value(3, k, c) * delta.z;
}

// How far from its own value channel c of the record may be extrapolated to p: the share of the gradient's
// change that keeps the mean between 0 and twice the record's.
double extrapolation(const VolumeRecord& r, const dvec3& delta, int c) {
    double mean = r.value(0, 0, c), dc = change(r, delta, 0, c);
    if (!(std::abs(dc) > std::abs(mean))) return 1;
    return std::abs(mean) / std::abs(dc);
}

double coefficientAt(const VolumeRecord& r, const dvec3& delta, double share, int k, int c) {
    return r.value(0, k, c) + share * change(r, delta, k, c);
}

// A peak's light at the record's point moved by delta: as of an equivalent point source where its ray met a
// surface (or at the source it samples), seen from p, the way to it turned and its light scaled by the
// inverse square of the new distance, at most 4 and at least 1/4 times its own (the zones keep within a
// third of the distance); from infinity it stays as it is.
struct MovedPeak {
    dvec3 dir;
    double scale;
};

MovedPeak movedPeak(const glm::vec4& ray, const dvec3& delta) {
    dvec3 dir(ray);
    if (!(ray.w > 0)) return {dir, 1};
    double d = 1 / double(ray.w);
    dvec3 to = dir * d - delta;
    double moved = glm::length(to);
    if (!(moved > 0)) return {dir, 4};
    return {to / moved, std::clamp(d * d / (moved * moved), 0.25, 4.0)};
}

}  // namespace

double VolumeZones::weigh(const VolumeRecord& r, const Receiver& at, Spectrum* value) const {
    dvec3 delta = at.point - r.point;
    double q = glm::length(delta) / r.radius;
    if (!(q < 1)) return 0;
    double w = q < 1e-6 ? 1e6 : 1 / q - 1;
    if (value) {
        const int ch = r.channels();
        *value = Spectrum(0.f, ch);
        for (int c = 0; c < ch; ++c)
            (*value)[c] = float(std::max(0.0, coefficientAt(r, delta, extrapolation(r, delta, c), 0, c)) * kShY0);
        for (int i = 0; i < r.peaks(); ++i) {
            double f = movedPeak(r.peakRays[i], delta).scale / (4 * std::numbers::pi);
            for (int c = 0; c < ch; ++c) (*value)[c] += float(r.flux(i, c) * f);
        }
    }
    return w;
}

Spectrum VolumeZones::scattered(const VolumeRecord& r, const dvec3& p, const dvec3& dir,
                                const std::array<double, kShCount>& y, const PhaseMixture& phase, bool sources) {
    const int ch = r.channels();
    const dvec3 delta = p - r.point;
    // Per channel, the sums of c_k Y_k(dir) of each order.
    std::array<Spectrum, 3> order{Spectrum(0.f, ch), Spectrum(0.f, ch), Spectrum(0.f, ch)};
    for (int c = 0; c < ch; ++c) {
        double share = extrapolation(r, delta, c);
        for (int k = 0; k < kShCount; ++k) order[shOrder(k)][c] += float(coefficientAt(r, delta, share, k, c) * y[k]);
    }
    Spectrum out(0.f, ch);
    phase.forEachLobe([&](const Spectrum& coefficient, double g) {
        for (int c = 0; c < ch; ++c)
            out[c] += coefficient[c] * std::max(0.f, order[0][c] + float(g) * (order[1][c] + float(g) * order[2][c]));
    });
    for (int i = 0; i < r.peaksWith(sources); ++i) {
        MovedPeak peak = movedPeak(r.peakRays[i], delta);
        Spectrum response = phase.response(dir, peak.dir);
        for (int c = 0; c < ch; ++c) out[c] += float(response[c] * r.flux(i, c) * peak.scale);
    }
    return out;
}

// The zone's box, widened for the float rounding of coordinates far from the origin.
ZoneBox VolumeZones::box(const VolumeRecord& r, const dvec3& origin) const {
    dvec3 p = r.point - origin;
    double reach = r.radius * 1.001 + 1e-6 * glm::length(p);
    ZoneBox b;
    for (int k = 0; k < 3; ++k) b.lo[k] = float(p[k] - reach), b.hi[k] = float(p[k] + reach);
    return b;
}

double VolumeZones::sizeBeforeRecords() const {
    return shape_.kind == RecordShape::Kind::Classic ? shape_.accuracy * shape_.maxRadius / 4 : shape_.maxRadius / 4;
}

void VolumeZones::shrinkToExclude(VolumeRecord& holder, const VolumeRecord& other) const {
    Spectrum value(0.f);
    Receiver at;
    at.point = other.point;
    if (weigh(holder, at, &value) <= 0) return;
    double seen = brightness(value), actual = brightness(other.meanRadiance());
    if (std::abs(seen - actual) <= 2 * shape_.accuracy * std::max(seen, actual)) return;
    double q = glm::length(other.point - holder.point) / holder.radius;
    holder.radius *= float(std::max(0.5, 0.999 * q));
}

void VolumeZones::shareZone(std::vector<VolumeRecord>& records) {
    float radius = records.front().radius;
    for (const VolumeRecord& r : records) radius = std::min(radius, r.radius);
    for (VolumeRecord& r : records) r.radius = radius;
}

void VolumeZones::reconcile(VolumeRecord& fresh, VolumeRecord& older) const {
    shrinkToExclude(older, fresh);
    shrinkToExclude(fresh, older);
}

}  // namespace brume
