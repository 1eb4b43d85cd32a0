#include "integrator/scatterer.h"

#include "material/ward.h"

namespace brume {

using namespace integrator_detail;

Spectrum Scatterer::phaseResponse(const dvec3& l, double lightDensity) const {
    double w = phaseSampled_ && lightDensity > 0 ? powerHeuristic(lightDensity, phase_->pdf(*dir_, l)) : 1.0;
    Spectrum f(0.f);
    f += phase_->response(*dir_, l) * float(w);
    return f;
}

Spectrum Scatterer::surfaceResponse(const dvec3& l, double lightDensity, bool withDiffuse) const {
    const Shading& sh = *surface_;
    const Lobes& lobes = *lobes_;
    dvec3 wo = -sh.dir;
    double cosL = glm::dot(sh.normal, l);
    Spectrum f(0.f);
    auto add = [&](const Spectrum& coef, double brdf, bool sampled, double density) {
        double w = sampled && lightDensity > 0 ? powerHeuristic(lightDensity, density) : 1.0;
        f += coef * float(brdf * std::abs(cosL) * w);
    };
    if (cosL > 0) {
        double fresnel = lobes.fresnelDiffuse ? 1 - fresnelEstimate(cosL) : 1.0;
        if (withDiffuse && !lobes.diffuse.isBlack()) add(lobes.diffuse, fresnel / kPi, false, 0);
        if (!lobes.glossy.isBlack())
            add(lobes.glossy, wardBrdf(wo, l, sh.normal, lobes.alpha2), lobes.sampleGlossy,
                wardPdf(wo, l, sh.normal, lobes.alpha2));
    } else if (cosL < 0) {
        double fresnel = lobes.fresnelDiffuse ? 1 - fresnelEstimate(-cosL) : 1.0;
        if (!lobes.diffuseTrans.isBlack()) add(lobes.diffuseTrans, fresnel / kPi, false, 0);
        if (!lobes.glossyTrans.isBlack())
            add(lobes.glossyTrans, gaussianBtdf(sh.dir, l, lobes.alphaT2, sh.cosine, -cosL), lobes.sampleGlossyTrans,
                gaussianTransmissionPdf(sh.dir, l, lobes.alphaT2));
    }
    if (lobes.general) {
        double w = lobes.sampleGeneral && lightDensity > 0 ? powerHeuristic(lightDensity, lobes.general->pdf(sh, l)) : 1.0;
        f += lobes.general->response(sh, l) * float(w);
    }
    return f;
}

}  // namespace brume
