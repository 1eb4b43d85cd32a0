#include "geometry/surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/polygon.h"
#include "util/error.h"

namespace brume {

namespace {

void expectArgs(const SceneObject& o, size_t reals) {
    if (!o.strings.empty() || !o.integers.empty() || o.reals.size() != reals)
        throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\": expected 0 strings, 0 integers, " +
                                 std::to_string(reals) + " reals");
}

dvec3 point(const SceneObject& o, size_t at) { return {o.reals[at], o.reals[at + 1], o.reals[at + 2]}; }

void requireFinite(const SceneObject& o) {
    for (double r : o.reals)
        if (!std::isfinite(r)) throw Error(o.where, "non-finite argument for " + o.type + " \"" + o.name + "\"");
}

// As Radiance: a negative radius turns the surface inside out (a sphere into a bubble, a cone into a cup),
// with a warning.
bool negativeRadius(const SceneObject& o, bool negative) {
    if (negative) warn(o.where.str() + ": negative radius for " + o.type + " \"" + o.name + "\"");
    return negative;
}

Shape sphere(const SceneObject& o) {
    expectArgs(o, 4);
    double r = o.reals[3];
    if (!(std::abs(r) > 0)) throw Error(o.where, "illegal radius for " + o.type + " \"" + o.name + "\"");
    return Sphere{point(o, 0), std::abs(r), (o.type == "bubble") != negativeRadius(o, r < 0)};
}

Shape cone(const SceneObject& o) {
    bool constantRadius = o.type == "cylinder" || o.type == "tube";
    expectArgs(o, constantRadius ? 7 : 8);
    double r0 = o.reals[6], r1 = constantRadius ? r0 : o.reals[7];
    dvec3 base = point(o, 0), top = point(o, 3);
    // Radiance refuses radii of opposite signs (or both zero), and turns a cone with negative ones inside out.
    auto sign = [](double r) { return r < 0 ? -1 : r > 0 ? 1 : 0; };
    if (sign(r0) + sign(r1) == 0)
        throw Error(o.where, "illegal radii for " + o.type + " \"" + o.name + "\"");
    bool inward = (o.type == "cup" || o.type == "tube") != negativeRadius(o, r0 < 0 || r1 < 0);
    if (glm::length(top - base) == 0) throw Error(o.where, "zero length " + o.type + " \"" + o.name + "\"");
    return Cone{base, top, std::abs(r0), std::abs(r1), inward};
}

Shape ring(const SceneObject& o) {
    expectArgs(o, 8);
    dvec3 n = point(o, 3);
    double r0 = o.reals[6], r1 = o.reals[7];
    if (glm::length(n) == 0) throw Error(o.where, "zero normal for ring \"" + o.name + "\"");
    if (r0 < 0 || r1 <= r0) throw Error(o.where, "illegal radii for ring \"" + o.name + "\"");
    return Ring{point(o, 0), glm::normalize(n), r0, r1};
}

}  // namespace

bool isSurfaceType(const std::string& t) {
    return t == "sphere" || t == "bubble" || t == "polygon" || t == "cone" || t == "cup" || t == "cylinder" ||
           t == "tube" || t == "ring";
}

std::optional<Surface> makeSurface(const Scene& scene, int index) {
    const SceneObject& o = scene.objects[index];
    requireFinite(o);
    if (o.type == "sphere" || o.type == "bubble") return Surface{index, sphere(o)};
    if (o.type == "ring") return Surface{index, ring(o)};
    if (o.type == "polygon") {
        if (!o.strings.empty() || !o.integers.empty() || o.reals.size() % 3 != 0 || o.reals.size() < 9)
            throw Error(o.where, "bad arguments for polygon \"" + o.name + "\": expected 3n reals, n >= 3");
        std::vector<dvec3> v;
        for (size_t i = 0; i < o.reals.size(); i += 3) v.push_back(point(o, i));
        std::string why;
        auto poly = makePolygon(std::move(v), why);
        if (!poly) {
            warn(o.where.str() + ": degenerate polygon \"" + o.name + "\" dropped (" + why + ")");
            return std::nullopt;
        }
        poly->triangles = triangulate(*poly);
        if (poly->triangles.empty()) {
            warn(o.where.str() + ": polygon \"" + o.name + "\" crosses itself, dropped");
            return std::nullopt;
        }
        return Surface{index, std::move(*poly)};
    }
    return Surface{index, cone(o)};
}

bool withinTraceableRange(const Shape& shape) {
    constexpr double kLimit = 1e18;
    auto ok = [](const dvec3& p, double r = 0) {
        return std::abs(p.x) + r <= kLimit && std::abs(p.y) + r <= kLimit && std::abs(p.z) + r <= kLimit;
    };
    struct {
        decltype(ok)& in;
        bool operator()(const Sphere& s) const { return in(s.center, s.radius); }
        bool operator()(const Cone& c) const {
            double r = std::max(c.baseRadius, c.topRadius);
            return in(c.base, r) && in(c.top, r);
        }
        bool operator()(const Ring& r) const { return in(r.center, r.outerRadius); }
        bool operator()(const Polygon& p) const {
            return std::all_of(p.vertices.begin(), p.vertices.end(), [&](const dvec3& v) { return in(v); });
        }
    } visit{ok};
    return std::visit(visit, shape);
}

Shape transformed(const Shape& shape, const Transform& t) {
    double k = std::abs(t.scale);
    struct {
        const Transform& t;
        double k;
        Shape operator()(const Sphere& s) const { return Sphere{t.point(s.center), s.radius * k, s.inward}; }
        Shape operator()(const Cone& c) const {
            return Cone{t.point(c.base), t.point(c.top), c.baseRadius * k, c.topRadius * k, c.inward};
        }
        Shape operator()(const Ring& r) const {
            return Ring{t.point(r.center), glm::normalize(t.vector(r.normal)), r.innerRadius * k, r.outerRadius * k};
        }
        Shape operator()(const Polygon& p) const {
            std::vector<dvec3> v;
            for (const dvec3& x : p.vertices) v.push_back(t.point(x));
            if (t.mirrors()) std::reverse(v.begin(), v.end());  // the winding turns with the mirror image
            std::string why;
            auto poly = makePolygon(std::move(v), why);
            if (!poly) throw Error("polygon degenerate once transformed (" + why + ")");
            poly->triangles = triangulate(*poly);
            return std::move(*poly);
        }
    } visit{t, k};
    return std::visit(visit, shape);
}

double area(const Shape& shape) {
    using std::numbers::pi;
    struct {
        double operator()(const Sphere& s) const { return 4 * pi * s.radius * s.radius; }
        double operator()(const Cone& c) const {
            double slant = std::hypot(glm::length(c.top - c.base), c.topRadius - c.baseRadius);
            return pi * (c.baseRadius + c.topRadius) * slant;
        }
        double operator()(const Ring& r) const { return pi * (r.outerRadius * r.outerRadius - r.innerRadius * r.innerRadius); }
        double operator()(const Polygon& p) const { return p.area; }
    } visit;
    return std::visit(visit, shape);
}

}  // namespace brume
