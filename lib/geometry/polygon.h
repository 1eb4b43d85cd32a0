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

}  // namespace brume
