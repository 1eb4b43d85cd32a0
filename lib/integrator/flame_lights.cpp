#include "integrator/flame_lights.h"

#include <limits>

#include "light/light.h"

namespace brume {

using namespace integrator_detail;

// One sample per ratio of the box's angular size on each axis, at most kMaxSamples: each sample is already an
// estimate along a whole direction, at several points, and costs as much as many shadow rays.
int FlameLights::sampleCount(const ParticipatingMedia& smoke, const dvec3& point, double subdivision, double weight) {
    constexpr int kMaxSamples = 16;
    const Bounds3& box = smoke.flameBox();
    double size = glm::length(box.hi - box.lo);
    double angularSize = size / std::max(glm::length(0.5 * (box.lo + box.hi) - point), 0.5 * size);
    return std::min(kMaxSamples, subdividedSampleCount(angularSize, 1, subdivision, weight));
}

Spectrum FlameLights::sample(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                             double subdivision, bool scatteredOnce, PathContext& ctx, double shareWithin) const {
    const ParticipatingMedia& smoke = ctx.smoke;
    if (!smoke.hasFlames()) return Spectrum(0.f);
    // Points along each direction: 4 (each of them weighs B and the flame's exact depth, nearly the same; 8 took
    // 40 % more time for a tenth less noise in make demo's flame picture), 2 deeper in a path, where many
    // paths average.
    const int n = sampleCount(smoke, at.point(), subdivision, state.weight), points = state.depth == 0 ? 4 : 2;
    return estimate(at, surface, state, n, points, scatteredOnce && smoke.scatters(HomogeneousMedium{}), shareWithin, ctx);
}

Spectrum FlameLights::estimate(const Scatterer& at, const SurfaceId& surface, const PathState& state, int n, int points,
                               bool scatteredOnce, double emittedShare, PathContext& ctx) const {
    const ParticipatingMedia& smoke = ctx.smoke;
    Spectrum sum(0.f);
    const dvec3& p = at.point();
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    for (int k = 0; k < n; ++k) {
        double u0, u1;
        sobol2D(k, scramble, u0, u1);
        double u2 = ctx.rng.uniform(), u3 = ctx.rng.uniform();
        std::optional<dvec3> drawn = smoke.sampleFlameDirection(p, u0, u1, u2, u3);
        if (!drawn) continue;
        const dvec3& dir = *drawn;
        double density = smoke.flameDirectionDensity(p, dir);
        if (!(density > 0)) continue;
        Spectrum f = at.response(dir, density * n);
        if (f.isBlack()) continue;
        // Along the direction, through the flames' box.
        double t0 = 0, t1 = std::numeric_limits<double>::infinity();
        if (!clipToBox(smoke.flameBox(), p, dir, t0, t1)) continue;
        Spectrum le = shadowRays_.flameLightAlong(Ray{p, dir, t1, surface}, points, state, ctx) * float(emittedShare);
        // What the soot scatters here of that emission, seen from a drawn ray's point inside the box, is light
        // scattered twice, which no sample of the ray's origin counts: all of it the ray's.
        if (scatteredOnce) le += scatteredWithin(p, dir, t0, t1, surface, state, ctx);
        if (!le.isBlack()) sum.addProduct(f, le, float(1 / (density * n)));
    }
    return sum;
}

Spectrum FlameLights::scatteredWithin(const dvec3& from, const dvec3& dir, double t0, double t1,
                                      const SurfaceId& surface, const PathState& state, PathContext& ctx) const {
    // A point where the smoke's first collision falls along the chord: σ_s T over its density is the albedo
    // (times the chance of a collision), whatever the smoke's depth, and the light there is what varies.
    std::optional<std::pair<double, double>> drawn = ctx.smoke.smokeCollision(Ray{from, dir}, t0, t1, ctx.rng.uniform());
    if (!drawn) return Spectrum(0.f);
    const auto [t, density] = *drawn;
    PathState walking = state;
    Spectrum through = shadowRays_.toSurface(Ray{from, dir, t, surface}, SurfaceId{}, false, Emitter::Kind::Light,
                                             walking, ctx, nullptr);
    if (through.isBlack()) return Spectrum(0.f);
    const dvec3 point = from + t * dir;
    PhaseMixture phase;
    ctx.smoke.scattering(point, HomogeneousMedium{}, through * float(1 / density), phase);
    if (phase.empty()) return Spectrum(0.f);
    // One sample of the flames' emission there: what lights the soot, not what it scatters again.
    return estimate(Scatterer(point, dir, phase, false), SurfaceId{}, state, 1, 2, false, 1, ctx);
}

std::optional<double> FlameLights::rayShare(const ParticipatingMedia& smoke, const PathState& state,
                                            const dvec3& dir) const {
    double density = smoke.flameDirectionDensity(state.from, dir);
    if (!(density > 0)) return std::nullopt;
    int n = sampleCount(smoke, state.from, state.fromSubdivision, state.fromWeight);
    return powerHeuristic(state.sampledDensity, density * n);
}

}  // namespace brume
