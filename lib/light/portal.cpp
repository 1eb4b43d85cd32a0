#include "light/portal.h"

#include "geometry/polygon.h"

namespace brume {

Portal::Portal(const Polygon& polygon, const SurfaceId& surface)
    : polygon_(&polygon), rectangle_(asRectangle(polygon)), points_(polygon), surface_(surface) {}

double Portal::projectedSolidAngle(const dvec3& p, const dvec3& n) const {
    return brume::projectedSolidAngle(polygon_->vertices, p, n);
}

bool Portal::crossedBy(const dvec3& p, const dvec3& dir) const {
    double t = polygon_->planeDistance(Ray(p, dir));
    if (!(t > 0) || !std::isfinite(t)) return false;
    dvec3 q = p + t * dir;
    const auto& v = polygon_->vertices;
    for (const auto& tri : polygon_->triangles) {
        // Inside the triangle: on the inner side of its three edges, as seen along the polygon's normal.
        dvec3 a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
        dvec3 n = glm::cross(b - a, c - a);
        if (glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
            glm::dot(glm::cross(a - c, q - c), n) >= 0)
            return true;
    }
    return false;
}

}  // namespace brume
