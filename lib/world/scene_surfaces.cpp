// Scene objects that are surfaces (sphere, bubble, polygon, cone, cup, cylinder, tube, ring) turned into
// exact shapes, with Radiance's checks of their arguments.
#include "world/scene_surfaces.h"

#include <cmath>

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

}  // namespace brume
