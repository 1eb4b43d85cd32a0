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

// A peak's light at the record's point moved by delta, relative to its own: as of an equivalent point source
// where its ray met a surface, to first order 1 + 2 ω·δ/d, kept between 0 and 2 as the harmonics' mean is.
double peakChange(const glm::vec4& ray, const dvec3& delta) {
    return 1 + std::clamp(2 * glm::dot(dvec3(ray), delta) * ray.w, -1.0, 1.0);
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
            double f = peakChange(r.peakRays[i], delta) / (4 * std::numbers::pi);
            for (int c = 0; c < ch; ++c) (*value)[c] += float(r.flux(i, c) * f);
        }
    }
    return w;
}

Spectrum VolumeZones::scattered(const VolumeRecord& r, const dvec3& p, const dvec3& dir,
                                const std::array<double, kShCount>& y, const PhaseMixture& phase) {
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
    for (int i = 0; i < r.peaks(); ++i) {
        const glm::vec4& ray = r.peakRays[i];
        Spectrum response = phase.response(dir, dvec3(ray));
        double change = peakChange(ray, delta);
        for (int c = 0; c < ch; ++c) out[c] += float(response[c] * r.flux(i, c) * change);
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

void VolumeZones::reconcile(VolumeRecord& fresh, VolumeRecord& older) const {
    shrinkToExclude(older, fresh);
    shrinkToExclude(fresh, older);
}

}  // namespace brume
