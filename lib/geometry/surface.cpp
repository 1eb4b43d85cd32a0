#include "geometry/surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/polygon.h"
#include "util/error.h"

namespace brume {

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
