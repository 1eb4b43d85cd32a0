#include "cache/volume_record_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace brume {

namespace {

// Φ's brightness, its gradient's and its curvature, Σ 2 E_i / d_i².
struct Variation {
    double fluence = 0, curvature = 0;
    dvec3 gradient{0};
};

// Light e from direction dir, as of a point source 1/d away (0: at infinity).
void add(Variation& v, double e, const dvec3& dir, double inverseDistance) {
    v.fluence += e;
    v.gradient += 2 * e * inverseDistance * dir;
    v.curvature += 2 * e * inverseDistance * inverseDistance;
}

Variation variation(const SphereSamples& s, const VolumeRecord& r) {
    Variation v;
    for (int i = 0; i < s.count(); ++i) {
        double d = s.distance(i);
        add(v, s.solidAngle() * s.brightness(i), s.direction(i), std::isfinite(d) ? 1 / d : 0);
    }
    const int ch = r.channels();
    for (int i = r.peaks() - r.sourcePeaks; i < r.peaks(); ++i) {
        Spectrum flux(0.f, ch);
        for (int c = 0; c < ch; ++c) flux[c] = r.flux(i, c);
        add(v, brightness(flux), dvec3(glm::vec3(r.peakRays[i])), r.peakRays[i].w);
    }
    return v;
}

// The distance to the nearest surface the samples' rays met (infinite: none).
double nearestSurface(const SphereSamples& s) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < s.count(); ++i) nearest = std::min(nearest, s.distance(i));
    return nearest;
}

double zoneRadius(const SphereSamples& s, const VolumeRecord& record, const RecordShape& shape, double nearestSource,
                  double extinction) {
    const double eps = shape.accuracy;
    // The transmittance to the light's sources changes by about e^(−σ_t δ) over a move δ: within ε at the edge.
    // The edge within √ε of its own distance to the nearest lamp: r ≤ √ε (D − r).
    const double nearLamp = std::sqrt(eps) * nearestSource / (1 + std::sqrt(eps));
    const double reach = std::min({nearLamp, nearestSurface(s), eps / std::max(extinction, 1e-300)});
    if (shape.kind == RecordShape::Kind::Classic)
        return std::min(eps * std::clamp(s.harmonicMeanDistance(), shape.minRadius, shape.maxRadius),
                        std::max(reach, eps * shape.minRadius));
    Variation v = variation(s, record);
    double r = v.curvature > 0 ? std::sqrt(2 * eps * v.fluence / v.curvature) : shape.maxRadius;
    double slope = glm::length(v.gradient);
    if (slope * r > v.fluence && slope > 0) r = v.fluence / slope;
    r = std::clamp(std::min(r, reach), eps * shape.minRadius, shape.maxRadius);
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

// A source's samples as peaks: its extent seen from the point, on the plane tangent to the samples' mean
// direction, cut into cells of about kCellAngle radians a side (at most kMaxCells along each axis), one peak
// per cell its samples fall in; a small or far source is one. Looking straight at a panel 0.6 m square 1 m
// away, HG .6 scatters of one peak at its centre 1.3 times the panel's light, of 2 × 2 cells 1.04 times, of
// 6 × 6 1.004 (g .9: 6.9, 1.33 and 1.025 times). Each peak goes the way of its samples' mean direction, at the
// mean of their inverse distances, both weighted by their light.
void addSourcePeaks(const SourceSamples& samples, VolumeRecord& r) {
    constexpr double kCellAngle = 0.05;
    constexpr int kMaxCells = 6;
    const int ch = r.channels();
    dvec3 mean(0);
    for (const SourceSample& s : samples) mean += double(brightness(s.flux)) * s.dir;
    if (!(glm::length(mean) > 0)) return;
    mean = glm::normalize(mean);
    const dvec3 u = glm::normalize(glm::cross(mean, std::abs(mean.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 v = glm::cross(mean, u);
    // Where each sample falls on the tangent plane (directions behind it, from a source all about the point,
    // to its edge).
    std::vector<glm::dvec2> at(samples.size());
    glm::dvec2 lo(1e300), hi(-1e300);
    for (size_t i = 0; i < samples.size(); ++i) {
        const dvec3& w = samples[i].dir;
        at[i] = glm::dvec2(glm::dot(w, u), glm::dot(w, v)) / std::max(glm::dot(w, mean), 0.1);
        lo = glm::min(lo, at[i]), hi = glm::max(hi, at[i]);
    }
    glm::ivec2 cells;
    for (int k = 0; k < 2; ++k) cells[k] = std::clamp(int(std::ceil((hi[k] - lo[k]) / kCellAngle)), 1, kMaxCells);
    auto cellOf = [&](size_t i) {
        glm::ivec2 c;
        for (int k = 0; k < 2; ++k)
            c[k] = std::min(cells[k] - 1, int((at[i][k] - lo[k]) / std::max(hi[k] - lo[k], 1e-300) * cells[k]));
        return c.x * cells.y + c.y;
    };
    const int count = cells.x * cells.y;
    std::vector<dvec3> dir(count, dvec3(0));
    std::vector<double> weight(count, 0.0), inverse(count, 0.0), flux(size_t(count) * ch, 0.0);
    for (size_t i = 0; i < samples.size(); ++i) {
        const SourceSample& s = samples[i];
        int c = cellOf(i);
        double b = brightness(s.flux);
        dir[c] += b * s.dir;
        weight[c] += b;
        inverse[c] += std::isfinite(s.distance) ? b / s.distance : 0;
        for (int k = 0; k < ch; ++k) flux[size_t(c) * ch + k] += s.flux[k];
    }
    for (int c = 0; c < count; ++c) {
        if (!(weight[c] > 0) || !(glm::length(dir[c]) > 0)) continue;
        r.peakRays.push_back(glm::vec4(glm::vec3(glm::normalize(dir[c])), float(inverse[c] / weight[c])));
        for (int k = 0; k < ch; ++k) r.peakFlux.push_back(float(flux[size_t(c) * ch + k]));
        ++r.sourcePeaks;
    }
}

}  // namespace

VolumeRecord buildVolumeRecord(const SphereSamples& s, const std::vector<SourceSamples>& sources,
                               const RecordShape& shape, int level, double nearestSource, double extinction) {
    VolumeRecord r;
    r.point = s.point();
    r.level = level;
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
    for (const SourceSamples& source : sources) addSourcePeaks(source, r);
    r.radius = float(zoneRadius(s, r, shape, nearestSource, extinction));
    return r;
}

}  // namespace brume
