// What scatters the light arriving at a point toward the viewer, as next-event estimation asks it: a
// surface's lobes (the hit as its material sees it), or a medium's phase functions. Surface and medium points
// share one light-sampling routine (LightSampler::sampleLd) through it.
#pragma once
#include <optional>

#include "integrator/path_state.h"
#include "material/material.h"
#include "medium/phase_mixture.h"

namespace brume {

// It refers to what it is made of, which outlives it (a light sample's call).
class Scatterer {
public:
    // At a surface hit.
    Scatterer(const Shading& sh, const Lobes& lobes) : point_(&sh.point), surface_(&sh), lobes_(&lobes) {}
    // In a medium, at `point` on a ray of direction `dir`; `sampledByRays`: the phase functions are also
    // sampled by a ray there (which then takes its share of the sources' light by multiple importance).
    Scatterer(const dvec3& point, const dvec3& dir, const PhaseMixture& phase, bool sampledByRays)
        : point_(&point), dir_(&dir), phase_(&phase), phaseSampled_(sampledByRays) {}

    const dvec3& point() const { return *point_; }
    // The hit, at a surface; null in a medium.
    const Shading* surface() const { return surface_; }

    // Whether some lobe is also sampled by rays: then each source's light is shared with those rays by the
    // power heuristic, which assumes every source sampled.
    bool sampledByRays() const {
        if (phase_) return phaseSampled_;
        return lobes_->sampleGlossy || lobes_->sampleGlossyTrans || (lobes_->general && lobes_->sampleGeneral);
    }
    // The Lambertian reflectance whose unoccluded light next-event estimation may take in closed form: a
    // surface's diffuse lobe, unless the Fresnel estimate scales it with the light's angle.
    const Spectrum* lambertian() const {
        return lobes_ && !lobes_->diffuse.isBlack() && !lobes_->fresnelDiffuse ? &lobes_->diffuse : nullptr;
    }
    // A surface that only reflects diffusely (no specular, glossy or transmitting lobe).
    bool onlyLambertian() const {
        return lambertian() && lobes_->deltaCount == 0 && lobes_->glossy.isBlack() && lobes_->glossyTrans.isBlack() &&
               lobes_->diffuseTrans.isBlack() && !lobes_->general;
    }
    // The cosine between the surface's normal and l (0 in a medium, where there is no normal).
    double cosine(const dvec3& l) const { return surface_ ? glm::dot(surface_->normal, l) : 0.0; }

    // The response f·|cos θ| (a surface) or f (a medium) to light from unit direction l. A lobe that is also
    // sampled by rays takes its power-heuristic share against the source's sampling density `lightDensity`;
    // lightDensity 0 gives every lobe all of it (sources no ray will count). Without `withDiffuse` the
    // Lambertian lobe is left out (next-event estimation has it in closed form).
    Spectrum response(const dvec3& l, double lightDensity, bool withDiffuse = true) const {
        return phase_ ? phaseResponse(l, lightDensity) : surfaceResponse(l, lightDensity, withDiffuse);
    }

private:
    Spectrum surfaceResponse(const dvec3& l, double lightDensity, bool withDiffuse) const;
    Spectrum phaseResponse(const dvec3& l, double lightDensity) const;

    const dvec3* point_;
    const Shading* surface_ = nullptr;
    const Lobes* lobes_ = nullptr;
    const dvec3* dir_ = nullptr;
    const PhaseMixture* phase_ = nullptr;
    bool phaseSampled_ = false;
};

}  // namespace brume
