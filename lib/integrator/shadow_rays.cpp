#include "integrator/shadow_rays.h"

namespace brume {

using namespace integrator_detail;

Spectrum ShadowRays::toSurface(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind,
                               PathState& state, PathContext& ctx, SurfaceHit* reached) const {
    Spectrum t(1.f);
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(ray);
        if (media_.present()) {
            t *= media_.transmittance(ray, 0, hit ? hit->t : ray.tmax,
                                      media_.homogeneousAlong(ray, hit ? &*hit : nullptr, state), ctx.smoke, ctx.rng);
            if (t.isBlack()) return t;
        }
        if (!hit) return toInfinity ? t : Spectrum(0.f);
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
    }
    return Spectrum(0.f);
}

}  // namespace brume
