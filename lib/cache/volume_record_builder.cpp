#include "cache/volume_record_builder.h"

#include <algorithm>
#include <cmath>

namespace brume {

namespace {

// Φ's brightness, its gradient's and its curvature, Σ 2 E_i / d_i².
struct Variation {
    double fluence = 0, curvature = 0;
    dvec3 gradient{0};
};

Variation variation(const SphereSamples& s) {
    Variation v;
    for (int i = 0; i < s.count(); ++i) {
        double e = s.solidAngle() * s.brightness(i), d = s.distance(i);
        v.fluence += e;
        if (!std::isfinite(d)) continue;
        v.gradient += 2 * e / d * s.direction(i);
        v.curvature += 2 * e / (d * d);
    }
    return v;
}

double zoneRadius(const SphereSamples& s, const RecordShape& shape, double nearestSource) {
    const double eps = shape.accuracy;
    if (shape.kind == RecordShape::Kind::Classic)
        return std::min(eps * std::clamp(s.harmonicMeanDistance(), shape.minRadius, shape.maxRadius),
                        std::max(std::sqrt(eps) * nearestSource, eps * shape.minRadius));
    Variation v = variation(s);
    double r = v.curvature > 0 ? std::sqrt(2 * eps * v.fluence / v.curvature) : shape.maxRadius;
    double slope = glm::length(v.gradient);
    if (slope * r > v.fluence && slope > 0) r = v.fluence / slope;
    r = std::clamp(std::min(r, std::sqrt(eps) * nearestSource), eps * shape.minRadius, shape.maxRadius);
    return std::isfinite(r) && r > 0 ? r : eps * shape.minRadius;
}

}  // namespace

VolumeRecord buildVolumeRecord(const SphereSamples& s, const RecordShape& shape, int level, double nearestSource) {
    VolumeRecord r;
    r.point = s.point();
    r.level = level;
    r.radius = float(zoneRadius(s, shape, nearestSource));
    const int ch = s.channels();
    r.values.assign(size_t(VolumeRecord::kFields) * kShCount * ch, 0.f);
    std::vector<double> sum(r.values.size(), 0.0);
    auto at = [&](int field, int k, int c) -> double& { return sum[(size_t(field) * kShCount + k) * ch + c]; };
    for (int i = 0; i < s.count(); ++i) {
        const dvec3& dir = s.direction(i);
        auto y = shBasis(dir);
        double d = s.distance(i);
        dvec3 toward = std::isfinite(d) ? 2 / d * dir : dvec3(0);
        for (int c = 0; c < ch; ++c) {
            double l = s.solidAngle() * s.radiance(i, c);
            for (int k = 0; k < kShCount; ++k) {
                double lk = l * y[k];
                at(0, k, c) += lk;
                for (int axis = 0; axis < 3; ++axis) at(1 + axis, k, c) += lk * toward[axis];
            }
        }
    }
    for (size_t j = 0; j < sum.size(); ++j) r.values[j] = float(sum[j]);
    return r;
}

}  // namespace brume
