#include "sampling/polygon_points.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "sampling/warp.h"

namespace brume {

PolygonPoints::PolygonPoints(const Polygon& polygon) : polygon_(&polygon) {
    double sum = 0;
    const auto& v = polygon.vertices;
    for (const auto& t : polygon.triangles) {
        sum += 0.5 * glm::length(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
        cdf_.push_back(sum);
    }
    for (double& c : cdf_) c /= sum;
}

dvec3 PolygonPoints::at(double u, double v) const {
    size_t t = pickAndReuse(cdf_, u);
    double b0, b1;
    uniformTriangle(u, v, b0, b1);
    const auto& tri = polygon_->triangles[t];
    const auto& vs = polygon_->vertices;
    return b0 * vs[tri[0]] + b1 * vs[tri[1]] + (1 - b0 - b1) * vs[tri[2]];
}

}  // namespace brume
