// Radiance polygons: any simple polygon, convex or not, and polygons with holes cut by a seam.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shapes.h"

namespace brume {

// The polygon through `vertices`, or nullopt with `why` set when it is degenerate (fewer than three
// distinct vertices, or no area).
std::optional<Polygon> makePolygon(std::vector<dvec3> vertices, std::string& why);

// Triangles (indices into polygon.vertices) covering exactly the polygon's inside by the even-odd rule, so
// that concave polygons and seamed holes are right. Empty if the outline crosses itself.
std::vector<std::array<int, 3>> triangulate(const Polygon& polygon);

// The polygon's solid angle projected on the plane of a point p facing n, which is also the irradiance a
// uniform polygon of unit radiance gives there (Lambert, 1760): ½ Σ γᵢ n·(rᵢ × rᵢ₊₁)/|rᵢ × rᵢ₊₁|, γᵢ the angle
// its edge i subtends, once the polygon is clipped to the half-space above p. Either side of it alike.
double projectedSolidAngle(const std::vector<dvec3>& vertices, const dvec3& p, const dvec3& n);

}  // namespace brume
