// The rays the estimators of one scattering spawn (specular children, sampled directions, a record's
// hemisphere, what lies behind a medium), traced by the integrator: the interface that lets surface
// scattering, media transport and the cache client be built and tested apart from it.
#pragma once
#include <optional>

#include "integrator/path_context.h"
#include "world/scene_geometry.h"

namespace brume {

class Tracer {
public:
    // The radiance arriving at ray.org along the ray. A sampled ray that meets a source next-event estimation
    // samples returns none of its light: that source's multiple-importance share goes to `sourceShare`, or
    // nowhere when it is null (a diffuse lobe's ray: next-event estimation counted it all). `record`, if
    // given, receives the ray's outputs (rtrace's -o letters).
    virtual Spectrum radiance(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare,
                              RayRecord* record = nullptr) const = 0;
    // The radiance of what a ray meets, `hit` or (none) what lies past every surface, leaving aside any
    // medium on its way.
    virtual Spectrum surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>& hit, const PathState& state,
                                     PathContext& ctx, Spectrum* sourceShare) const = 0;
    // A ray drawn from a lobe at `from` (leaving `surface`) in direction `dir` with density `pdf`, as `child`
    // of `parent` (whose roulette made it): what it brings back, the sources it meets weighted against
    // next-event estimation.
    virtual Spectrum sampledRadiance(const dvec3& from, const SurfaceId& surface, const dvec3& dir, double pdf,
                                     const PathState& parent, PathState& child, PathContext& ctx) const = 0;

protected:
    ~Tracer() = default;
};

}  // namespace brume
