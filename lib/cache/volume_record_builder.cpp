#include "cache/volume_record_builder.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

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

// The share of each sample's light kept as a peak: of those brighter than twice the median sample (the
// background: a peak's own samples would raise a mean), their excess over that level (the level stays in the
// harmonics, which then see a plateau, not a hole: cutting whole samples out of a bump would leave a notch
// order 2 cannot hold either), for the kMaxPeaks largest excesses; 0 for the others. Where most samples are
// dark (a median of 0), the level is the mean.
std::vector<double> peakShares(const SphereSamples& s) {
    constexpr size_t kMaxPeaks = 32;
    std::vector<float> b(s.count());
    double mean = 0;
    for (int i = 0; i < s.count(); ++i) mean += (b[i] = s.brightness(i)) / s.count();
    std::nth_element(b.begin(), b.begin() + b.size() / 2, b.end());
    const double level = b[b.size() / 2] > 0 ? 2.0 * b[b.size() / 2] : mean;
    std::vector<std::pair<double, int>> above;
    for (int i = 0; i < s.count(); ++i)
        if (s.brightness(i) > level && level > 0) above.push_back({s.brightness(i) - level, i});
    std::sort(above.begin(), above.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    above.resize(std::min(above.size(), kMaxPeaks));
    std::vector<double> share(s.count(), 0.0);
    for (const auto& [excess, i] : above) share[i] = excess / s.brightness(i);
    return share;
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
    const std::vector<double> peak = peakShares(s);
    for (int i = 0; i < s.count(); ++i) {
        const dvec3& dir = s.direction(i);
        auto y = shBasis(dir);
        double d = s.distance(i);
        dvec3 toward = std::isfinite(d) ? 2 / d * dir : dvec3(0);
        if (peak[i] > 0) r.peakRays.push_back(glm::vec4(glm::vec3(dir), std::isfinite(d) ? float(1 / d) : 0.f));
        for (int c = 0; c < ch; ++c) {
            double l = s.solidAngle() * s.radiance(i, c);
            if (peak[i] > 0) r.peakFlux.push_back(float(peak[i] * l));
            l *= 1 - peak[i];
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
