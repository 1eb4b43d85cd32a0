#include "light/light.h"

#include <cmath>
#include <numbers>

#include "geometry/polygon.h"
#include "sampling/warp.h"

namespace brume {

namespace {
constexpr double kPi = std::numbers::pi;
// Polygons are sampled by solid angle when they have few triangles and look larger than this (sr);
// smaller ones are sampled by area, which is then just as uniform in solid angle.
constexpr double kMinSolidAngle = 1e-4;

// 1 − cos of the half-angle under which a sphere of radius r is seen from distance d > r, without
// cancellation for small spheres.
double sphereOneMinusCos(double r, double d) {
    double sin2 = (r / d) * (r / d);
    return sin2 / (1 + std::sqrt(std::max(0.0, 1 - sin2)));
}

// A regular 16-gon about `centre` in the plane across unit `axis`, enclosing the circle of radius r (with
// 1.3% more area).
void circleOutline(const dvec3& centre, const dvec3& axis, double r, std::vector<dvec3>& out) {
    constexpr int kSides = 16;
    dvec3 e1 = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    dvec3 e2 = glm::cross(axis, e1);
    double reach = r / std::cos(kPi / kSides);
    for (int k = 0; k < kSides; ++k) {
        double a = 2 * kPi * k / kSides;
        out.push_back(centre + reach * (std::cos(a) * e1 + std::sin(a) * e2));
    }
}

}  // namespace

Light::Light(const Surface& surface, SurfaceId id, const Emitter* emitter, bool patterned)
    : shape_(&surface.shape), surface_(id), object_(surface.object), emitter_(emitter), patterned_(patterned) {
    area_ = area(surface.shape);
    size_ = std::sqrt(area_);
    if (const auto* s = std::get_if<Sphere>(shape_)) center_ = s->center, size_ = 2 * s->radius;
    else if (const auto* c = std::get_if<Cone>(shape_)) center_ = 0.5 * (c->base + c->top);
    else if (const auto* r = std::get_if<Ring>(shape_)) center_ = r->center;
    if (const auto* poly = std::get_if<Polygon>(shape_)) {
        points_ = PolygonPoints(*poly);
        for (const dvec3& v : poly->vertices) center_ += v / double(poly->vertices.size());
        rectangle_ = asRectangle(*poly);
    }
}

Light::Light(const dvec3& direction, double angle, const Emitter* emitter, int object, bool patterned)
    : object_(object), emitter_(emitter), patterned_(patterned), direction_(glm::normalize(direction)) {
    double half = std::min(angle, 2 * kPi) / 2;
    // 2 sin²(θ/2) keeps the sun's tiny cone exact; 1 − cos θ keeps a hemisphere's edge exactly at 1.
    oneMinusCos_ = half < 0.5 ? 2 * std::sin(half / 2) * std::sin(half / 2) : 1 - std::cos(half);
}

// With a margin of a few ulps, so a hemisphere's edge (the horizon of a 180° sky) belongs to it.
bool Light::distantContains(const dvec3& d) const { return 1 - glm::dot(d, direction_) <= oneMinusCos_ + 1e-12; }

int subdividedSampleCount(double angularSize, double perAxis, double ratio, double weight) {
    if (ratio <= 0) return 1;
    int n = static_cast<int>(std::ceil(std::min(16.0, perAxis * angularSize * weight / ratio)));
    return std::max(1, n * n);
}

int Light::sampleCount(const dvec3& p, double ratio, double weight) const {
    double angularSize = isDistant() ? 2 * std::sqrt(2 * oneMinusCos_) : size_ / std::max(glm::length(center_ - p), 1e-300);
    // One stratified sample per axis where Radiance makes one partition for sources whose unoccluded diffuse
    // light has a closed form (shadow rays then only find what is blocked, see LightSampler::directFrom); two for
    // the others, whose random positions need them to be as smooth as Radiance's fixed cell centres.
    return subdividedSampleCount(angularSize, hasClosedForm() ? 1 : 2, ratio, weight);
}

double Light::roughSolidAngle(const dvec3& p) const {
    if (isDistant()) return 2 * kPi * oneMinusCos_;
    double d2 = glm::dot(center_ - p, center_ - p), s2 = size_ * size_;
    return s2 / std::max(d2, s2);
}

void Light::pointOnSurface(double u, double v, dvec3& point, dvec3& normal) const {
    if (const auto* poly = std::get_if<Polygon>(shape_)) {
        point = points_.at(u, v);
        normal = poly->normal;
    } else if (const auto* ring = std::get_if<Ring>(shape_)) {
        double r2in = ring->innerRadius * ring->innerRadius, r2out = ring->outerRadius * ring->outerRadius;
        double r = std::sqrt(r2in + u * (r2out - r2in)), phi = 2 * kPi * v;
        Frame f(ring->normal);
        point = ring->center + r * (std::cos(phi) * f.s + std::sin(phi) * f.t);
        normal = ring->normal;
    } else {
        const auto& c = std::get<Cone>(*shape_);  // a cylinder: lights on cones are refused earlier
        dvec3 axis = c.top - c.base;
        Frame f(glm::normalize(axis));
        double phi = 2 * kPi * v;
        normal = std::cos(phi) * f.s + std::sin(phi) * f.t;
        point = c.base + u * axis + c.baseRadius * normal;
        if (c.inward) normal = -normal;
    }
}

std::optional<LightSample> Light::sampleArea(const dvec3& p, double u, double v) const {
    dvec3 x, n;
    pointOnSurface(u, v, x, n);
    dvec3 toLight = x - p;
    double dist = glm::length(toLight);
    if (!(dist > 0)) return std::nullopt;
    dvec3 dir = toLight / dist;
    double cosLight = -glm::dot(n, dir);
    if (cosLight <= 0) return std::nullopt;  // emitters radiate from their front only
    return LightSample{dir, dist, dist * dist / (area_ * cosLight), n};
}

// Front-lit polygons with few triangles are sampled by solid angle: their spherical triangles from p.
LightView Light::view(const dvec3& p) const {
    const auto* poly = std::get_if<Polygon>(shape_);
    if (!poly || glm::dot(poly->normal, p - poly->vertices[0]) <= 0) return LightView{p};
    LightView v{p, SphericalPolygon(p, *poly, rectangle_)};
    double total = v.polygon.solidAngle();
    v.solidAngle = total >= kMinSolidAngle && std::isfinite(total) ? total : 0;
    return v;
}

std::optional<LightSample> Light::sampleSolidAngle(const LightView& view, double u, double v) const {
    const auto& poly = std::get<Polygon>(*shape_);
    double dist;
    dvec3 dir = view.polygon.sample(u, v, dist);
    double cosLight = -glm::dot(poly.normal, dir);
    if (!(dist > 0) || cosLight <= 0) return std::nullopt;
    return LightSample{dir, dist, 1 / view.solidAngle, poly.normal};
}

std::optional<LightSample> Light::sample(const LightView& view, double u, double v) const {
    std::optional<LightSample> s = sampleShape(view, u, v);
    if (s && !emitter_->emitsToward(-s->dir)) return std::nullopt;
    return s;
}

std::optional<LightSample> Light::sampleShape(const LightView& view, double u, double v) const {
    if (view.solidAngle > 0) return sampleSolidAngle(view, u, v);
    const dvec3& p = view.point;
    if (isDistant()) {
        dvec3 dir = Frame(direction_).toWorld(uniformCone(u, v, oneMinusCos_));
        return LightSample{dir, std::numeric_limits<double>::infinity(), 1 / (2 * kPi * oneMinusCos_), -dir};
    }
    const auto* sphere = std::get_if<Sphere>(shape_);
    if (!sphere) return sampleArea(p, u, v);
    // Uniform over the cone the sphere subtends: exact solid angle, no wasted samples on its far side.
    dvec3 toCenter = sphere->center - p;
    double dc = glm::length(toCenter);
    if (dc <= sphere->radius) return std::nullopt;
    double omc = sphereOneMinusCos(sphere->radius, dc);
    dvec3 dir = Frame(toCenter / dc).toWorld(uniformCone(u, v, omc));
    // Distance to the near side of the sphere along dir.
    double b = glm::dot(dir, toCenter);
    double h2 = std::max(0.0, sphere->radius * sphere->radius - (dc * dc - b * b));
    double dist = b - std::sqrt(h2);
    return LightSample{dir, dist, 1 / (2 * kPi * omc), glm::normalize(p + dist * dir - sphere->center)};
}

namespace {

// A disc of angular radius α (1 − cos α given) whose centre is at angle β from the normal, wholly above
// the horizon: π sin²α cos β.
double capIrradiance(double oneMinusCosAlpha, double cosBeta) {
    double sin2 = oneMinusCosAlpha * (2 - oneMinusCosAlpha);
    double sinBeta = std::sqrt(std::max(0.0, 1 - cosBeta * cosBeta));
    double cosAlpha = 1 - oneMinusCosAlpha;
    // Above the horizon: α + β ≤ 90°, i.e. cos(α + β) ≥ 0.
    if (cosAlpha * cosBeta - std::sqrt(sin2) * sinBeta < 0) return -1;
    return kPi * sin2 * cosBeta;
}

}  // namespace

bool Light::hasClosedForm() const {
    bool uniform = !patterned_ && (emitter_->kind == Emitter::Kind::Light || emitter_->kind == Emitter::Kind::Illum);
    return uniform && (isDistant() || std::holds_alternative<Polygon>(*shape_) || std::holds_alternative<Sphere>(*shape_));
}

double Light::unoccludedIrradiance(const dvec3& p, const dvec3& n) const {
    if (!hasClosedForm()) return -1;
    if (isDistant()) return capIrradiance(oneMinusCos_, glm::dot(n, direction_));
    if (const auto* poly = std::get_if<Polygon>(shape_)) {
        if (glm::dot(poly->normal, p - poly->vertices[0]) <= 0) return 0;  // behind its front
        return projectedSolidAngle(poly->vertices, p, n);
    }
    if (const auto* sphere = std::get_if<Sphere>(shape_)) {
        dvec3 toCenter = sphere->center - p;
        double d = glm::length(toCenter);
        if (d <= sphere->radius) return -1;
        return capIrradiance(sphereOneMinusCos(sphere->radius, d), glm::dot(n, toCenter / d));
    }
    return -1;
}

double Light::pdf(const dvec3& p, const dvec3& dir, double distance, const dvec3& hitNormal) const {
    if (isDistant()) return distantContains(dir) ? 1 / (2 * kPi * oneMinusCos_) : 0;
    if (const auto* sphere = std::get_if<Sphere>(shape_)) {
        double dc = glm::length(sphere->center - p);
        return dc > sphere->radius ? 1 / (2 * kPi * sphereOneMinusCos(sphere->radius, dc)) : 0;
    }
    if (std::holds_alternative<Polygon>(*shape_))
        if (LightView v = view(p); v.solidAngle > 0) return 1 / v.solidAngle;
    double cosLight = -glm::dot(hitNormal, dir);
    return cosLight > 0 ? distance * distance / (area_ * cosLight) : 0;
}

std::vector<dvec3> Light::outline(const dvec3& eye) const {
    std::vector<dvec3> out;
    if (isDistant()) {  // the cone of directions, on the plane one unit along it
        double half = std::acos(1 - oneMinusCos_);
        circleOutline(eye + direction_, direction_, std::tan(half), out);
        return out;
    }
    if (const auto* poly = std::get_if<Polygon>(shape_)) {
        if (glm::dot(eye - poly->vertices[0], poly->normal) <= 0) return out;  // seen from behind: dark
        return poly->vertices;
    }
    if (const auto* sphere = std::get_if<Sphere>(shape_)) {
        // The tangent cone from the eye meets the plane through the centre in a circle of radius r·D/√(D²−r²).
        dvec3 toCentre = sphere->center - eye;
        double d2 = glm::dot(toCentre, toCentre), r2 = sphere->radius * sphere->radius;
        if (d2 <= r2) return out;
        circleOutline(sphere->center, toCentre / std::sqrt(d2), sphere->radius * std::sqrt(d2 / (d2 - r2)), out);
    } else if (const auto* ring = std::get_if<Ring>(shape_)) {
        circleOutline(ring->center, ring->normal, ring->outerRadius, out);
    } else if (const auto* cone = std::get_if<Cone>(shape_)) {
        dvec3 axis = glm::normalize(cone->top - cone->base);
        circleOutline(cone->base, axis, cone->baseRadius, out);
        circleOutline(cone->top, axis, cone->topRadius, out);
    }
    return out;
}

}  // namespace brume
