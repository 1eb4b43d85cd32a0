// A flat polygon as seen from a point: its solid angle and directions uniform over it — one spherical
// rectangle for rectangles (most luminaires and windows), else its spherical triangles. Seen from either side.
#pragma once
#include <optional>
#include <variant>

#include "geometry/shapes.h"
#include "sampling/spherical_rectangle.h"
#include "sampling/spherical_triangle.h"

namespace brume {

// A four-sided polygon whose corners make right angles, as a rectangle: one spherical rectangle samples it
// more evenly than two spherical triangles. Within 1e-9 of its size, so that rectangles whose corners were
// rounded to 12 digits (xform's output) still count; the rectangle sampled then differs from the polygon by
// that much, far below single-precision values.
std::optional<Rectangle> asRectangle(const Polygon& poly);

class SphericalPolygon {
public:
    static constexpr size_t kMaxTriangles = 8;  // polygons with more are not sampled by solid angle

    SphericalPolygon() = default;
    // `poly` (its rectangle, if it is one) seen from p; no solid angle where it has more than kMaxTriangles
    // triangles. The polygon must outlive the view.
    SphericalPolygon(const dvec3& p, const Polygon& poly, const std::optional<Rectangle>& rectangle);

    double solidAngle() const { return solidAngle_; }
    const dvec3& point() const { return point_; }
    // The direction for (u, v) in the unit square, uniform in solid angle, and the distance along it to the
    // polygon's plane.
    dvec3 sample(double u, double v, double& distance) const;

private:
    struct Triangles {
        SphericalTriangle of[kMaxTriangles];
    };
    dvec3 point_{0};
    const Polygon* polygon_ = nullptr;
    // Only the form in use is made and copied: a view is made per shading point and source.
    std::variant<std::monostate, SphericalRectangle, Triangles> form_;
    double solidAngle_ = 0;
};

}  // namespace brume
