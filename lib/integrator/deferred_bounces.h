// Bounces whose diffuse continuation is left to someone else. A sensor's -ad rays meet surfaces whose light
// from the rest of the scene (bounces past the first) is smooth: where a run pools those continuations
// between nearby hits (shared bounces, lib/render/shared_bounces.h: rcontrib's, rtrace's sensors'), the first
// hit of each ray still gathers its own direct light, sky through windows and sun patches, but hands its
// cosine-distributed continuation to a BounceSink with the throughput that continuation's radiance would carry.
#pragma once
#include <cstdint>

#include "geometry/ray.h"
#include "spectrum/spectrum.h"

namespace brume {

struct DeferredBounce {
    dvec3 point;        // where the continuation leaves
    glm::vec3 normal;   // into the hemisphere of this unit normal
    SurfaceId surface;  // the surface it leaves
    int object;         // that surface's scene object: bounces pool only on one object
    float distance;     // from the point the query's -ad rays left (how large a blur it can bear)
    float weight;       // the continuation's Radiance weight (for -lw)
    int16_t reflections, depth;
};

class BounceSink {
public:
    // `throughput`: what a unit of the continuation's radiance adds to the query's value.
    virtual void defer(const DeferredBounce& bounce, const Spectrum& throughput) = 0;

protected:
    ~BounceSink() = default;
};

}  // namespace brume
