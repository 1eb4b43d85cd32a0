#include "view/aperture.h"

#include <glm/geometric.hpp>

#include <cmath>

#include "sampling/warp.h"

namespace brume {

bool jitterAperture(const View& view, ViewRay& ray, double diameter, double u1, double u2, double u3) {
    if (diameter <= 1e-6) return true;
    double focus = glm::length(view.vd);
    dvec3 forward = view.vd / focus;
    dvec3 right = glm::normalize(glm::cross(forward, glm::normalize(view.vu)));
    dvec3 up = glm::cross(right, forward);
    double dx, dy;
    concentricDisk(u1, u2, dx, dy);
    dvec3 lens = 0.5 * diameter * (dx * right + dy * up);
    dvec3 origin, target;
    switch (view.type) {
    case kPerspective:
        origin = view.vp + lens;
        target = view.vp + focus / glm::dot(ray.dir, forward) * ray.dir;
        break;
    case kParallel: {
        // Each pixel keeps its own place on the lens plane; Radiance's jitteraperture moves every pixel's
        // origin to the view point, so that its parallel views with -pd all see one point.
        dvec3 pixel = ray.org - view.vo * forward;
        origin = pixel + lens;
        target = pixel + focus * forward;
        break;
    }
    default:
        // Radiance also jitters the depth of the lens for the fisheyes and panoramas.
        origin = view.vp + lens + M_PI / 4 * diameter * (.5 - u3) * forward;
        target = view.vp + focus * ray.dir;
        break;
    }
    dvec3 dir = target - origin;
    double length = glm::length(dir);
    if (!(length > 0)) return false;
    ray.dir = dir / length;
    ray.org = origin;
    if (view.vo > 1e-6)
        ray.org += (view.type == kPerspective ? view.vo / glm::dot(ray.dir, forward) : view.vo) * ray.dir;
    return true;
}

}  // namespace brume
