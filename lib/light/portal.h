// A window toward the sky: a flat, clear glazing through which points indoors see the sky and the ground,
// glows at infinity that only rays find otherwise. Next-event estimation aims at portals instead of waiting
// for a random diffuse ray to pass through one (Bitterli et al.'s portal sampling, "Portal-Masked
// Environment Map Sampling", EGSR 2015, in its simplest form: uniform in the portal's solid angle).
#pragma once
#include <optional>

#include "geometry/surface.h"
#include "sampling/polygon_points.h"
#include "sampling/spherical_polygon.h"

namespace brume {

class Portal {
public:
    // The polygon (the scene's) must outlive the portal.
    Portal(const Polygon& polygon, const SurfaceId& surface);

    // The portal as a point p sees it (from either side), to sample directions through it.
    SphericalPolygon view(const dvec3& p) const { return SphericalPolygon(p, *polygon_, rectangle_); }
    // The solid angle it fills over a point p facing n, projected on p's plane (cosine-weighted, as diffuse
    // light is).
    double projectedSolidAngle(const dvec3& p, const dvec3& n) const;
    // Whether a ray from p along unit dir passes through the portal.
    bool crossedBy(const dvec3& p, const dvec3& dir) const;
    // The point of the portal for (u, v) in the unit square, uniform in area.
    dvec3 pointAt(double u, double v) const { return points_.at(u, v); }
    double area() const { return polygon_->area; }
    const SurfaceId& surface() const { return surface_; }
    const Polygon& polygon() const { return *polygon_; }

private:
    const Polygon* polygon_;
    std::optional<Rectangle> rectangle_;
    PolygonPoints points_;
    SurfaceId surface_;
};

}  // namespace brume
