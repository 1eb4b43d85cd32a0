// Light along rays through participating media: attenuation, and light scattered toward the ray by the
// media it crosses, by null-collision tracking through the homogeneous medium and the smoke together.
// Rays whose value is the answer (primary rays and their specular children) see what lies behind the
// medium weighted by its transmittance, flames' light summed along them (ParticipatingMedia::emittedAlong)
// and in-scattering at points forced into the medium; rays averaged with many others (diffuse and sampled
// ones) take the sources' light at one such point and the rest at delta tracking's first collision, or the
// surface behind. Where scattering points find volume records, these give the light there: the sources' too
// where the ray has not taken it elsewhere (LightSampler::besidesRecords says what they leave out).
#pragma once
#include "integrator/cache_client.h"
#include "integrator/light_sampler.h"
#include "integrator/media.h"
#include "integrator/tracer.h"

namespace brume {

class MediaTransport {
public:
    MediaTransport(const RenderScene& scene, const RenderSettings& settings, const LightSampler& lights,
                   const CacheClient& cache, const Tracer& tracer, const RussianRoulette& roulette)
        : scene_(scene), settings_(settings), lights_(lights), cache_(cache), tracer_(tracer), roulette_(roulette) {}

    // The radiance along a ray that crosses media (`h` the homogeneous one along it) to `hit`, or past every
    // surface: what lies behind them as they let it through, and what they scatter and emit toward the ray.
    Spectrum along(const Ray& ray, const std::optional<SurfaceHit>& hit, const HomogeneousMedium& h,
                   const PathState& state, PathContext& ctx, Spectrum* sourceShare) const;

private:
    // What in-scattering sums: all the light, or the sources' that next-event estimation samples.
    enum class Part { All, Sources };
    // `keepsShares`: the ray's sources' shares count (its parent takes them, Tracer::sampledRadiance).
    Spectrum inScattered(const Ray& ray, double start, double end, const HomogeneousMedium& h, const PathState& state,
                         PathContext& ctx, Part part, bool keepsShares = false) const;
    Spectrum scattered(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, const PathState& state,
                       PathContext& ctx) const;
    Spectrum indirect(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, const PathState& state,
                      PathContext& ctx) const;
    // What the volume records say the phase at `point` scatters along the ray (true; the sources' light only
    // with `sources`), or false: no record (the path samples that light itself).
    bool fromRecords(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, bool sources,
                     const PathState& state, PathContext& ctx, Spectrum& value) const;
    Spectrum continued(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, const PathState& state,
                       PathContext& ctx, bool sharesSources) const;
    int inScatteringSamples(double length, bool fromRecords, bool flames) const;
    double flameShareAt(const dvec3& point, const dvec3& dir, const PathState& state, bool keepsShares,
                        PathContext& ctx) const;
    bool collisionsShine(bool emits, const PathState& state) const;

    const RenderScene& scene_;
    const RenderSettings& settings_;
    const LightSampler& lights_;
    const CacheClient& cache_;
    const Tracer& tracer_;
    const RussianRoulette& roulette_;
};

}  // namespace brume
