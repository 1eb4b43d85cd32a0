#include "cache/record_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace brume {

namespace {

constexpr double kPi = std::numbers::pi;

// A vector in the tangent plane, in the samples' frame (s, t).
struct Tangent {
    double x = 0, y = 0;
};

// Per channel: E and its translational (Ward–Heckbert) and rotational gradients, in the frame.
struct Measured {
    std::vector<double> irradiance;
    std::vector<Tangent> along, tilt;
};

Measured measure(const HemisphereSamples& hs) {
    const int rows = hs.rows(), cols = hs.columns(), ch = hs.channels();
    Measured m{std::vector<double>(ch, 0.0), std::vector<Tangent>(ch), std::vector<Tangent>(ch)};
    const double cell = kPi / hs.count();
    for (int i = 0; i < hs.count(); ++i) {
        const dvec3& d = hs.direction(i);
        double cosTheta = std::max(glm::dot(d, hs.frame().n), 1e-3);
        double tx = glm::dot(d, hs.frame().s) / cosTheta, ty = glm::dot(d, hs.frame().t) / cosTheta;
        for (int c = 0; c < ch; ++c) {
            double l = hs.radiance(i, c);
            m.irradiance[c] += cell * l;
            m.tilt[c].x += cell * l * tx;
            m.tilt[c].y += cell * l * ty;
        }
    }
    // Aimed samples as equivalent point sources: tilting the normal scales each by cos θ, moving the point
    // changes I cos θ / d² by 3E (ω·s)/d along the tangent s.
    for (const AimedSample& a : hs.aimed()) {
        double cosTheta = std::max(glm::dot(a.dir, hs.frame().n), 1e-3);
        Tangent toward{glm::dot(a.dir, hs.frame().s), glm::dot(a.dir, hs.frame().t)};
        double perDistance = std::isfinite(a.distance) && a.distance > 0 ? 3 / a.distance : 0;
        for (int c = 0; c < ch; ++c) {
            double e = a.irradiance[c];
            m.irradiance[c] += e;
            m.tilt[c].x += e * toward.x / cosTheta, m.tilt[c].y += e * toward.y / cosTheta;
            m.along[c].x += e * toward.x * perDistance, m.along[c].y += e * toward.y * perDistance;
        }
    }
    // Each pass's strata give the gradient again; their mean is the record's.
    auto nearer = [&](int a, int b) { return std::min(hs.distance(a), hs.distance(b)); };
    const double perPass = 1.0 / hs.passes();
    for (int p = 0; p < hs.passes(); ++p) {
        for (int k = 0; k < cols; ++k) {
            double phiMid = kPi * (2 * k + 1) / cols, phiEdge = hs.phiEdge(k);
            Tangent u{std::cos(phiMid), std::sin(phiMid)}, v{-std::sin(phiEdge), std::cos(phiEdge)};
            int previous = (k + cols - 1) % cols;
            for (int j = 0; j < rows; ++j) {
                int here = hs.cell(j, k, p), below = hs.cell(std::max(j - 1, 0), k, p), beside = hs.cell(j, previous, p);
                // The wall between rows j-1 and j moves as the point does (its nearer side decides how fast).
                double rowWall = 0, columnWall = 0;
                if (j > 0) {
                    double sin2 = hs.sin2Edge(j);
                    rowWall = perPass * 2 * kPi / cols * std::sqrt(sin2) * (1 - sin2) / nearer(here, below);
                }
                columnWall = perPass * (std::sqrt(hs.sin2Edge(j + 1)) - std::sqrt(hs.sin2Edge(j))) / nearer(here, beside);
                for (int c = 0; c < ch; ++c) {
                    double l = hs.radiance(here, c);
                    if (j > 0) {
                        double dl = rowWall * (l - hs.radiance(below, c));
                        m.along[c].x += u.x * dl, m.along[c].y += u.y * dl;
                    }
                    double dl = columnWall * (l - hs.radiance(beside, c));
                    m.along[c].x += v.x * dl, m.along[c].y += v.y * dl;
                }
            }
        }
    }
    return m;
}

// The symmetric 2×2 matrix [[a, b], [b, c]] and its eigen decomposition, largest eigenvalue first.
struct Symmetric2 {
    double a = 0, b = 0, c = 0;
    void addOuter(const Tangent& v, double w) { a += w * v.x * v.x, b += w * v.x * v.y, c += w * v.y * v.y; }
    void eigen(double lambda[2], Tangent& first) const {
        double mean = (a + c) / 2, d = std::sqrt((a - c) * (a - c) / 4 + b * b);
        lambda[0] = mean + d, lambda[1] = mean - d;
        if (std::abs(b) < 1e-30 * (std::abs(a) + std::abs(c)) || b == 0) {
            first = a >= c ? Tangent{1, 0} : Tangent{0, 1};
            return;
        }
        double x = b, y = lambda[0] - a, len = std::hypot(x, y);
        first = {x / len, y / len};
    }
};

// Each sample as an equivalent point source that may be an occluder's edge: the absolute curvature of
// I cos θ / d² as the point moves, 3E_i/d² · (|5 sin²θ − 1| along the source's direction, 1 across it).
Symmetric2 curvatureBound(const HemisphereSamples& hs) {
    Symmetric2 h;
    auto add = [&](const dvec3& dir, double e, double d) {
        if (!std::isfinite(d)) return;
        Tangent t{glm::dot(dir, hs.frame().s), glm::dot(dir, hs.frame().t)};
        double sin2 = t.x * t.x + t.y * t.y;
        double w = 3 * e / (d * d);
        if (sin2 < 1e-12) {
            h.a += w * 4, h.c += w * 4;  // overhead: 5 sin²θ − 1 = −1 both ways
            return;
        }
        double s = std::sqrt(sin2);
        Tangent along{t.x / s, t.y / s}, across{-along.y, along.x};
        h.addOuter(along, w * std::abs(5 * sin2 - 1));
        h.addOuter(across, w);
    };
    const double cell = kPi / hs.count();
    for (int i = 0; i < hs.count(); ++i) add(hs.direction(i), cell * hs.brightness(i), hs.distance(i));
    for (const AimedSample& a : hs.aimed()) add(a.dir, brightness(a.irradiance), a.distance);
    return h;
}

// What the equivalent point sources predict at `p`, a point of the record's plane: they keep their
// intensities and positions; their distance and angle change.
double predicted(const HemisphereSamples& hs, const dvec3& p) {
    const dvec3& n = hs.frame().n;
    double sum = 0;
    auto add = [&](const dvec3& dir, double e, double d) {
        if (!std::isfinite(d)) {
            sum += e;
            return;
        }
        double cosTheta = glm::dot(dir, n);
        if (cosTheta <= 1e-6) return;
        double intensity = e * d * d / cosTheta;
        dvec3 to = hs.point() + d * dir - p;
        double len2 = glm::dot(to, to), along = glm::dot(to, n);
        if (along > 0 && len2 > 0) sum += intensity * along / (len2 * std::sqrt(len2));
    };
    const double cell = kPi / hs.count();
    for (int i = 0; i < hs.count(); ++i) add(hs.direction(i), cell * hs.brightness(i), hs.distance(i));
    for (const AimedSample& a : hs.aimed()) add(a.dir, brightness(a.irradiance), a.distance);
    return sum;
}

double brightnessOf(const std::vector<double>& v) { return brume::brightnessOf(v, int(v.size())); }

Tangent brightnessOf(const std::vector<Tangent>& v) {
    std::vector<double> x(v.size()), y(v.size());
    for (size_t c = 0; c < v.size(); ++c) x[c] = v[c].x, y[c] = v[c].y;
    return {brightnessOf(x), brightnessOf(y)};
}

dvec3 world(const HemisphereSamples& hs, const Tangent& t) { return t.x * hs.frame().s + t.y * hs.frame().t; }

// Shortens each axis until the extrapolation to its ends and the point sources' prediction there agree.
void shortenToAgree(const HemisphereSamples& hs, double e, const dvec3& gradient, double epsilon, double smallest,
                    SurfaceRecord& r) {
    const dvec3 axes[2] = {r.axis, r.axis2()};
    for (int k = 0; k < 2; ++k) {
        for (int step = 0; step < 12 && r.radius[k] > smallest; ++step) {
            double worst = 0;
            for (double sign : {-1.0, 1.0}) {
                dvec3 offset = sign * double(r.radius[k]) * axes[k];
                double extrapolated = e + glm::dot(gradient, offset);
                worst = std::max(worst, std::abs(predicted(hs, hs.point() + offset) - extrapolated));
            }
            if (worst <= epsilon * e) break;
            r.radius[k] = float(std::max(smallest, 0.75 * r.radius[k]));
        }
    }
}

}  // namespace

double RecordShape::maxAngle() const { return 10 * kPi / 180 + accuracy; }

SurfaceRecord buildRecord(const HemisphereSamples& hs, const RecordShape& shape, int level) {
    Measured m = measure(hs);
    SurfaceRecord r;
    r.point = hs.point();
    r.normal = hs.frame().n;
    r.level = level;
    const double eps = shape.accuracy;
    double e = brightnessOf(m.irradiance);
    Tangent g = brightnessOf(m.along);
    double radius[2];
    Tangent first{1, 0};
    if (shape.kind == RecordShape::Kind::Classic) {
        radius[0] = radius[1] = eps * std::clamp(hs.harmonicMeanDistance(), shape.minRadius, shape.maxRadius);
    } else {
        double lambda[2];
        curvatureBound(hs).eigen(lambda, first);
        for (int k = 0; k < 2; ++k)
            radius[k] = lambda[k] > 0 ? std::sqrt(2 * eps * e / lambda[k]) : shape.maxRadius;
    }
    r.axis = world(hs, first);
    const dvec3 axes[2] = {r.axis, r.axis2()};
    const dvec3 gradient = world(hs, g);
    for (int k = 0; k < 2; ++k) {
        // An extrapolation may at most double or zero the value at the zone's edge.
        double slope = std::abs(glm::dot(gradient, axes[k]));
        if (slope * radius[k] > e && slope > 0) radius[k] = e / slope;
        if (shape.kind == RecordShape::Kind::Adaptive)
            radius[k] = std::clamp(radius[k], eps * shape.minRadius, shape.maxRadius);
        if (!(radius[k] > 0) || !std::isfinite(radius[k])) radius[k] = eps * shape.minRadius;
        r.radius[k] = float(radius[k]);
    }
    if (shape.kind == RecordShape::Kind::Adaptive) {
        // At most 4:1, so that a noisy curvature cannot stretch a zone across a change it did not see.
        r.radius[1] = std::min(r.radius[1], 4 * r.radius[0]);
        if (e > 0) shortenToAgree(hs, e, gradient, eps, eps * shape.minRadius, r);
    }
    const int ch = hs.channels();
    Spectrum value(0.f, ch), alongK1(0.f, ch), alongK2(0.f, ch), tiltK1(0.f, ch), tiltK2(0.f, ch);
    for (int c = 0; c < ch; ++c) {
        value[c] = float(m.irradiance[c]);
        dvec3 along = world(hs, m.along[c]), tilt = world(hs, m.tilt[c]);
        alongK1[c] = float(glm::dot(along, axes[0]));
        alongK2[c] = float(glm::dot(along, axes[1]));
        tiltK1[c] = float(glm::dot(tilt, axes[0]));
        tiltK2[c] = float(glm::dot(tilt, axes[1]));
    }
    r.setField(SurfaceRecord::kIrradiance, value);
    r.setField(SurfaceRecord::kAlongK1, alongK1);
    r.setField(SurfaceRecord::kAlongK2, alongK2);
    r.setField(SurfaceRecord::kTiltK1, tiltK1);
    r.setField(SurfaceRecord::kTiltK2, tiltK2);
    return r;
}

}  // namespace brume
