#include "sampling/spherical_polygon.h"

namespace brume {

std::optional<Rectangle> asRectangle(const Polygon& poly) {
    if (poly.vertices.size() != 4) return std::nullopt;
    const auto& v = poly.vertices;
    dvec3 ex = v[1] - v[0], ey = v[3] - v[0];
    double scale = glm::dot(ex, ex) + glm::dot(ey, ey);
    dvec3 gap = v[2] - (v[1] + ey);
    if (std::abs(glm::dot(ex, ey)) > 1e-9 * scale || glm::dot(gap, gap) > 1e-18 * scale) return std::nullopt;
    return Rectangle{v[0], ex, ey - glm::dot(ex, ey) / glm::dot(ex, ex) * ex};
}

SphericalPolygon::SphericalPolygon(const dvec3& p, const Polygon& poly, const std::optional<Rectangle>& rectangle)
    : point_(p), polygon_(&poly) {
    if (rectangle) {
        solidAngle_ = form_.emplace<SphericalRectangle>(p, *rectangle).solidAngle();
        return;
    }
    if (poly.triangles.size() > kMaxTriangles) return;
    Triangles& tris = form_.emplace<Triangles>();
    for (size_t i = 0; i < poly.triangles.size(); ++i) {
        const auto& t = poly.triangles[i];
        tris.of[i] = SphericalTriangle(p, poly.vertices[t[0]], poly.vertices[t[1]], poly.vertices[t[2]]);
        solidAngle_ += tris.of[i].solidAngle();
    }
}

// u picks a triangle in proportion to its solid angle, then places the sample within it.
dvec3 SphericalPolygon::sample(double u, double v, double& distance) const {
    if (const auto* rectangle = std::get_if<SphericalRectangle>(&form_)) {
        dvec3 toPoint = rectangle->sample(u, v) - point_;
        distance = glm::length(toPoint);
        return toPoint / distance;
    }
    const SphericalTriangle* tris = std::get<Triangles>(form_).of;
    size_t n = polygon_->triangles.size(), i = 0;
    double target = u * solidAngle_, below = 0;
    while (i + 1 < n && below + tris[i].solidAngle() < target) below += tris[i++].solidAngle();
    double w = tris[i].solidAngle();
    dvec3 dir = tris[i].sample(w > 0 ? std::clamp((target - below) / w, 0.0, 1.0) : 0.0, v);
    distance = polygon_->planeDistance(Ray(point_, dir));
    return dir;
}

}  // namespace brume
