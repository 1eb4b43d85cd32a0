#include "integrator/shadow_rays.h"

namespace brume {

using namespace integrator_detail;

Spectrum ShadowRays::toSurface(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind,
                               PathState& state, PathContext& ctx, SurfaceHit* reached) const {
    return walk(ray, target, toInfinity, targetKind, state, ctx, reached,
                [&](const Ray& stretch, double end, const HomogeneousMedium& h, const Spectrum&) {
                    return ctx.smoke.transmittance(stretch, 0, end, h);
                });
}

Spectrum ShadowRays::flameLightAlong(const Ray& ray, int points, PathState state, PathContext& ctx) const {
    Spectrum sum(0.f);
    walk(ray, SurfaceId{}, false, Emitter::Kind::Light, state, ctx, nullptr,
         [&](const Ray& stretch, double end, const HomogeneousMedium& h, const Spectrum& before) {
             Spectrum t;
             sum += before * ctx.smoke.emittedAlong(stretch, 0, end, h, ctx.rng, t, points);
             return t;
         });
    return sum;
}

template <class Stretch>
Spectrum ShadowRays::walk(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind,
                          PathState& state, PathContext& ctx, SurfaceHit* reached, const Stretch& stretch) const {
    Spectrum t(1.f);
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(ray);
        if (media_.present()) {
            t *= stretch(ray, hit ? hit->t : ray.tmax, media_.homogeneousAlong(ray, hit ? &*hit : nullptr, state), t);
            if (t.isBlack()) return t;
        }
        if (!hit) return toInfinity || std::isfinite(ray.tmax) ? t : Spectrum(0.f);
        // The source itself: its pattern is the caller's, only its material matters here, so the shading
        // most shadow rays end on is skipped.
        bool onTarget = hit->surface == target;
        Shading sh;
        if (!onTarget) sh = shadingAt(ray, *hit, false, scene_.objectFrame(hit->surface));
        int mat = onTarget ? scene_.materialObject(target)
                           : shading_.shaderAt(ray, *hit, sh, ctx.rng, ctx.scratch.patterns);
        if (shading_.passes(mat, glm::dot(hit->normal, ray.dir) > 0, state)) {
            ray.org = hit->point;
            ray.leaving = hit->surface;
            ray.tmax -= hit->t;
            continue;
        }
        if (onTarget) {
            if (reached) *reached = *hit;
            return t;
        }
        const Emitter* e = scene_.emitter(mat);
        if (e && e->kind != Emitter::Kind::Illum) return Spectrum(0.f);  // another source blocks
        // An illum stands for the light coming through it: it hides other illums and glows behind it.
        if (e && !sh.backside && (targetKind == Emitter::Kind::Illum || targetKind == Emitter::Kind::Glow))
            return Spectrum(0.f);
        // Otherwise a shadow ray crosses an illum as it would its alternate material.
        const Material* m =
            e ? shading_.alternateMaterial(ray, *hit, *e, sh, ctx.rng, ctx.scratch.patterns) : scene_.material(mat);
        if (m) {
            dvec3 dir = ray.dir;
            t *= m->shadowTransmission(sh, dir);
            if (t.maxValue() <= 1e-6f) return Spectrum(0.f);
            ray.dir = dir;
        }
        ray.org = hit->point;
        ray.leaving = hit->surface;
        ray.tmax -= hit->t;
    }
    return Spectrum(0.f);
}

}  // namespace brume
