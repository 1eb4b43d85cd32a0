// Light sources for next-event estimation: emitting surfaces (polygon, ring, sphere, cylinder) and
// sources at infinity (`source`, e.g. the sun). Each is sampled with a density in solid angle that the
// integrator also evaluates for multiple importance sampling.
#pragma once
#include <optional>
#include <vector>

#include "geometry/surface.h"
#include "light/emitter.h"
#include "sampling/polygon_points.h"
#include "sampling/spherical_polygon.h"

namespace brume {

// A direction toward a source; its radiance is the emitter's (no spectrum per sample: the integrator reads
// it where a shadow ray gets through).
struct LightSample {
    dvec3 dir;        // unit, from the shading point toward the source
    double distance;  // to the sampled point (infinity for distant sources)
    double pdf;       // per unit solid angle
    dvec3 normal;     // the source's surface normal at the sampled point (−dir for distant sources)
};

// A source as seen from one shading point: what sampling it there needs, computed once for all its samples.
struct LightView {
    dvec3 point;
    SphericalPolygon polygon;  // of a polygon seen from its front
    double solidAngle = 0;  // > 0 when the polygon is sampled by solid angle
};

// Radiance-like subdivision: how many samples a source of angular size `angularSize` (radians, its size over
// its distance) gets for the -ds ratio and a ray's weight: `perAxis` per ratio of angle on each of two axes
// (at most 16), so at least 1.
int subdividedSampleCount(double angularSize, double perAxis, double ratio, double weight);

class Light {
public:
    // An emitting surface, in world coordinates; `id` tells it from others. A patterned source's radiance
    // varies over it and with direction: the integrator multiplies samples by its pattern.
    Light(const Surface& surface, SurfaceId id, const Emitter* emitter, bool patterned = false);
    // A source at infinity: unit direction and full cone angle in radians.
    Light(const dvec3& direction, double angle, const Emitter* emitter, int object, bool patterned = false);

    // Radiance-like subdivision: more samples for a source large as seen from p (-ds ratio, ray weight).
    int sampleCount(const dvec3& p, double ratio, double weight) const;
    LightView view(const dvec3& p) const;
    // A direction toward the source from the view's point for the point (u, v) of the unit square; nullopt
    // where the point cannot see the source's front or the sample carries no light (outside a spotlight's cone).
    std::optional<LightSample> sample(const LightView& view, double u, double v) const;
    // The solid-angle density with which sample() picks the direction that reached point `hit` (with the
    // source's normal there) from p.
    double pdf(const dvec3& p, const dvec3& dir, double distance, const dvec3& hitNormal) const;

    // The irradiance per unit radiance the whole source would give a surface at p facing n, if nothing were
    // in the way, in closed form (Lambert's polygon formula; πsin²α·cosβ for spheres and distant discs wholly
    // above the surface's horizon); negative where no closed form is used.
    double unoccludedIrradiance(const dvec3& p, const dvec3& n) const;
    // A rough, cheap guess of the solid angle the source fills seen from p (its size over its distance,
    // squared; a distant source's cone), to choose among sources: positive wherever it may give light.
    double roughSolidAngle(const dvec3& p) const;
    // Uniform sources shaped as polygons, spheres or distant discs: unoccludedIrradiance may answer.
    bool hasClosedForm() const;
    bool patterned() const { return patterned_; }
    bool isDistant() const { return !surface_; }
    const dvec3& direction() const { return direction_; }  // of a distant source
    // Of a surface: the middle of its shape and its size (the square root of its area, a sphere's diameter).
    const dvec3& center() const { return center_; }
    double size() const { return size_; }
    const SurfaceId& surface() const { return surface_; }  // none for distant sources
    int object() const { return object_; }
    const Emitter& emitter() const { return *emitter_; }
    // Whether a ray in direction d that escapes the scene meets this distant source.
    bool distantContains(const dvec3& d) const;
    // Points whose outline, as seen from `eye`, encloses the source: a polygon's corners, 16-gons about
    // round shapes (their silhouettes), for a distant source points one unit from the eye. Empty when the eye
    // is inside a sphere's or behind a flat source.
    std::vector<dvec3> outline(const dvec3& eye) const;

private:
    std::optional<LightSample> sampleShape(const LightView& view, double u, double v) const;
    std::optional<LightSample> sampleArea(const dvec3& p, double u, double v) const;
    std::optional<LightSample> sampleSolidAngle(const LightView& view, double u, double v) const;
    void pointOnSurface(double u, double v, dvec3& point, dvec3& normal) const;

    const Shape* shape_ = nullptr;
    SurfaceId surface_;
    int object_ = -1;
    const Emitter* emitter_;
    bool patterned_ = false;
    double area_ = 0;
    dvec3 center_{0};  // for the subdivision count
    double size_ = 0;
    PolygonPoints points_;  // of polygons
    std::optional<Rectangle> rectangle_;  // polygons that are rectangles
    dvec3 direction_{0};               // distant
    double oneMinusCos_ = 0;           // distant: 1 − cos(half angle)
};

}  // namespace brume
