// Points uniform in area over a polygon: a triangle chosen in proportion to its area, then a point within it.
#pragma once
#include <vector>

#include "geometry/shapes.h"

namespace brume {

class PolygonPoints {
public:
    PolygonPoints() = default;
    // The polygon must outlive this.
    explicit PolygonPoints(const Polygon& polygon);
    // The point for (u, v) in the unit square (u picks the triangle, then is reused within it).
    dvec3 at(double u, double v) const;

private:
    const Polygon* polygon_ = nullptr;
    std::vector<double> cdf_;  // cumulative share of the area of its triangles
};

}  // namespace brume
