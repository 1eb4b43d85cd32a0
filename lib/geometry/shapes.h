// Radiance's surface primitives with exact (not tessellated) intersection in double precision.
// Orientation follows Radiance: sphere, cone and cylinder face outward; bubble, cup and tube inward;
// polygons face the side from which their vertices turn counter-clockwise; rings face along their axis.
#pragma once
#include <array>
#include <glm/geometric.hpp>
#include <optional>
#include <vector>

#include "geometry/ray.h"

namespace brume {

// Where a ray met a shape: the distance and the oriented geometric normal there.
struct ShapeHit {
    double t;
    dvec3 normal;
};

struct Sphere {
    dvec3 center;
    double radius;
    bool inward;  // bubble
    std::optional<ShapeHit> intersect(const Ray& ray, bool leavingThis) const;
};

// Cone, cup, cylinder and tube: a truncated cone between two end points, open at both ends.
struct Cone {
    dvec3 base, top;
    double baseRadius, topRadius;
    bool inward;  // cup, tube
    std::optional<ShapeHit> intersect(const Ray& ray, bool leavingThis) const;
};

// A disk with an optional hole, facing along its normal.
struct Ring {
    dvec3 center, normal;
    double innerRadius, outerRadius;
    std::optional<ShapeHit> intersect(const Ray& ray) const;
};

// A planar polygon, flat-shaded with the area-weighted (Newell) normal, like Radiance.
struct Polygon {
    std::vector<dvec3> vertices;
    dvec3 normal;  // unit
    double area;
    double planeOffset;  // normal · any vertex
    std::vector<std::array<int, 3>> triangles;  // indices into vertices covering the inside
    // The distance along the ray to the polygon's plane (the exact hit once a triangle was found).
    double planeDistance(const Ray& ray) const { return (planeOffset - glm::dot(normal, ray.org)) / glm::dot(normal, ray.dir); }
};

// The roots of a t² + b t + c = 0 in increasing order, computed without cancellation; false if none.
bool solveQuadratic(double a, double b, double c, double& t0, double& t1);

}  // namespace brume
