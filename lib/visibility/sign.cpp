#include "visibility/sign.h"

#include <limits>

#include "sampling/polygon_points.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/polygon.h"
#include "util/error.h"

namespace brume {

namespace {

double triangleArea(const Polygon& p, const std::array<int, 3>& t) {
    return 0.5 * glm::length(glm::cross(p.vertices[t[1]] - p.vertices[t[0]], p.vertices[t[2]] - p.vertices[t[0]]));
}

// The i-th of n points of a two-dimensional rank-1 lattice (Fibonacci-like, generator (1, 0.618…·n)), shifted
// by half a cell: stratified in both directions for any n.
void latticePoint(int i, int n, double& u, double& v) {
    const double golden = 0.6180339887498949;
    u = (i + 0.5) / n;
    v = std::fmod((i + 0.5) * golden, 1.0);
}

}  // namespace

bool facing(const Sign& sign, const dvec3& eye) { return glm::dot(sign.shape.normal, eye - sign.centre) > 0; }

const char* signKindName(SignKind kind) { return kind == SignKind::Emitting ? "emitting" : "reflecting"; }

double jinConstant(SignKind kind) { return kind == SignKind::Emitting ? 8 : 3; }

double legibilityFactor(SignKind kind) { return kind == SignKind::Emitting ? 200 : 100; }

Sign signFromScene(const Scene& scene, const std::string& name, SignKind kind, double jinConstant) {
    Sign sign;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.name != name || o.type != "polygon") continue;
        if (sign.object >= 0)
            throw Error(scene.objects[size_t(sign.object)].where.str() + ": sign '" + name + "': two polygons have this name (" +
                        o.where.str() + ")");
        sign.object = int(i);
    }
    if (sign.object < 0) throw Error("sign '" + name + "': no polygon of this name in the scene");
    const SceneObject& o = scene.objects[size_t(sign.object)];
    std::vector<dvec3> vertices;
    for (size_t r = 0; r + 2 < o.reals.size(); r += 3) vertices.push_back({o.reals[r], o.reals[r + 1], o.reals[r + 2]});
    std::string why;
    std::optional<Polygon> shape = makePolygon(vertices, why);
    if (shape) shape->triangles = triangulate(*shape);
    if (!shape || shape->triangles.empty()) throw Error(o.where.str() + ": sign '" + name + "': " + (shape ? "crosses itself" : why));
    sign.name = name;
    sign.kind = kind;
    sign.jinConstant = jinConstant;
    sign.shape = *shape;
    for (const auto& t : shape->triangles)
        sign.centre += triangleArea(*shape, t) *
                       (shape->vertices[t[0]] + shape->vertices[t[1]] + shape->vertices[t[2]]) / 3.0;
    sign.centre /= shape->area;
    const dvec3& n = shape->normal;
    dvec3 up = dvec3(0, 0, 1) - n * n.z;
    if (glm::length(up) < 1e-6) up = dvec3(0, 1, 0) - n * n.y;
    up = glm::normalize(up);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const dvec3& v : shape->vertices) lo = std::min(lo, glm::dot(v, up)), hi = std::max(hi, glm::dot(v, up));
    sign.height = hi - lo;
    return sign;
}

bool insidePolygon(const Polygon& p, const dvec3& q) {
    for (const auto& t : p.triangles) {
        const dvec3 &a = p.vertices[t[0]], &b = p.vertices[t[1]], &c = p.vertices[t[2]];
        dvec3 n = glm::cross(b - a, c - a);
        if (glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
            glm::dot(glm::cross(a - c, q - c), n) >= 0)
            return true;
    }
    return false;
}

std::vector<dvec3> pointsOnSign(const Sign& sign, int n) {
    std::vector<dvec3> points;
    PolygonPoints area(sign.shape);
    for (int i = 0; i < n; ++i) {
        double u, v;
        latticePoint(i, n, u, v);
        points.push_back(area.at(v, u));
    }
    return points;
}

std::vector<dvec3> pointsAroundSign(const Sign& sign, int n, double grow) {
    Polygon grown = sign.shape;
    for (dvec3& v : grown.vertices) v = sign.centre + grow * (v - sign.centre);
    grown.area *= grow * grow;
    // The points of a lattice over the grown polygon that fall outside the sign: m (1 − 1/grow²) of them.
    // Taking all of them (not the first n) keeps them spread over the whole band.
    const int m = int(std::ceil(n / (1 - 1 / (grow * grow))));
    std::vector<dvec3> points;
    PolygonPoints area(grown);
    for (int i = 0; i < m; ++i) {
        double u, v;
        latticePoint(i, m, u, v);
        dvec3 p = area.at(v, u);
        if (!insidePolygon(sign.shape, p)) points.push_back(p);
    }
    return points;
}

}  // namespace brume
