#include "integrator/surface_scattering.h"

#include "integrator/contributions.h"
#include "material/ward.h"
#include "sampling/warp.h"

namespace brume {

using namespace integrator_detail;

Spectrum SurfaceScattering::shade(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                  const PathState& state, PathContext& ctx, Spectrum* sourceShare) const {
    Spectrum value(0.f);
    double strongest = 0;
    RayOutputs* recorded = ctx.recording();
    for (int k = 0; k < lobes.deltaCount; ++k) {
        const DeltaLobe& d = lobes.delta[k];
        PathState child;
        float boost;
        if (!roulette_.spawn(state, child, d.weight, !d.transmits, ctx.rng, boost)) continue;
        // Shadow rays cross straight-through transmissions too, so sources seen through them were already
        // counted at the sampled ray's origin; any other specular bend makes a path only rays can find.
        bool straight = d.transmits && glm::dot(glm::normalize(d.dir), sh.dir) > 1 - 1e-12;
        bool stillSampled = straight && state.kind == PathState::Kind::Sampled;
        if (!stillSampled) child.kind = PathState::Kind::Specular;
        if (state.kind == PathState::Kind::Sampled && !d.transmits && lights_.mirrorImagesOn() &&
            scene_.isPlanarMirror(surface))
            child.viaMirror = surface.surface;
        RayRecord childRecord;
        Spectrum share(0.f), throughput;
        carryThroughput(state, child, d.weight * boost, throughput);
        Spectrum li = tracer_.radiance(Ray{sh.point, glm::normalize(d.dir), std::numeric_limits<double>::infinity(), surface},
                                       child, ctx, stillSampled ? &share : nullptr, recorded ? &childRecord : nullptr);
        if (sourceShare && !share.isBlack()) *sourceShare += d.weight * share * boost;
        Spectrum part = d.weight * li * boost;
        value += part;
        if (recorded) recorded->specularPart(part, !d.transmits, childRecord, strongest);
    }
    bool diffuseOrGlossy = !lobes.diffuse.isBlack() || !lobes.diffuseTrans.isBlack() || !lobes.glossy.isBlack() ||
                           !lobes.glossyTrans.isBlack() || lobes.general;
    if (diffuseOrGlossy)
        value += lights_.sampleLd(Scatterer(sh, lobes), surface, state, ctx, patches_.active() ? &patches_ : nullptr);
    if (lobes.sampleGlossy || lobes.sampleGlossyTrans) value += glossy(sh, lobes, surface, state, ctx);
    if (lobes.general && lobes.sampleGeneral) value += general(sh, *lobes.general, surface, state, ctx);
    value += ambient(sh, lobes, surface, state, ctx);
    if (recorded) recorded->shaded(value, strongest);
    return value.clampFinite();
}

// One ray per sampled glossy lobe, weighted against next-event estimation where it meets a source.
Spectrum SurfaceScattering::glossy(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                   const PathState& state, PathContext& ctx) const {
    Spectrum sum(0.f);
    dvec3 wo = -sh.dir;
    for (bool transmit : {false, true}) {
        if (!(transmit ? lobes.sampleGlossyTrans : lobes.sampleGlossy)) continue;
        const Spectrum& coef = transmit ? lobes.glossyTrans : lobes.glossy;
        double alpha2 = transmit ? lobes.alphaT2 : lobes.alpha2;
        PathState child;
        float boost;
        if (!roulette_.spawn(state, child, coef, !transmit, ctx.rng, boost)) continue;
        double u = ctx.rng.uniform(), v = ctx.rng.uniform();
        dvec3 wi = transmit ? sampleGaussianTransmission(sh.dir, alpha2, u, v) : sampleWard(wo, sh.normal, alpha2, u, v);
        double cosI = glm::dot(wi, sh.normal);
        if (transmit ? cosI >= 0 : cosI <= 0) continue;  // the sample left the lobe's side: no contribution
        double pdf = transmit ? gaussianTransmissionPdf(sh.dir, wi, alpha2) : wardPdf(wo, wi, sh.normal, alpha2);
        double f = transmit ? gaussianBtdf(sh.dir, wi, alpha2, sh.cosine, -cosI) : wardBrdf(wo, wi, sh.normal, alpha2);
        if (!(pdf > 0)) continue;
        Spectrum throughput;
        if (state.throughput) carryThroughput(state, child, coef * float(f * std::abs(cosI) / pdf * boost), throughput);
        sum += coef * tracer_.sampledRadiance(sh.point, surface, wi, pdf, state, child, ctx) *
               float(f * std::abs(cosI) / pdf * boost);
    }
    return sum;
}

// One sampled ray for a general lobe, weighted against next-event estimation where it meets a source.
Spectrum SurfaceScattering::general(const Shading& sh, const GeneralLobe& lobe, const SurfaceId& surface,
                                    const PathState& state, PathContext& ctx) const {
    double u = ctx.rng.uniform(), v = ctx.rng.uniform();
    auto s = lobe.sample(sh, u, v);
    if (!s || !(s->pdf > 0) || s->weight.isBlack()) return Spectrum(0.f);
    PathState child;
    float boost;
    if (!roulette_.spawn(state, child, s->weight, !s->transmits, ctx.rng, boost)) return Spectrum(0.f);
    Spectrum throughput;
    carryThroughput(state, child, s->weight * boost, throughput);
    return s->weight * tracer_.sampledRadiance(sh.point, surface, s->dir, s->pdf, state, child, ctx) * boost;
}

// Diffuse interreflection on each side with a diffuse coefficient: from the irradiance cache, or by path
// tracing (-ad cosine-distributed, stratified paths at the first bounce and one after it; one where the
// cache has no record yet deeper in a path), for -ab bounces; beyond them Radiance's -av value, or with the
// cache, paths ended by Russian roulette. Sources these paths meet are left out: next-event estimation
// counted them. The sky seen through windows and the sun's patches are aimed at too (SkyPortals, SunPatches):
// aimedCount(paths) samples of each.
Spectrum SurfaceScattering::ambient(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                    const PathState& state, PathContext& ctx) const {
    Spectrum sum(0.f);
    for (bool transmit : {false, true}) {
        const Spectrum& coef = transmit ? lobes.ambientTrans : lobes.ambient;
        if (coef.isBlack()) continue;
        bool beyond = state.ambientLevel >= settings_.ambientBounces;
        if ((beyond && !settings_.bounceTail()) || settings_.ambientDivisions <= 0) {
            sum += coef * settings_.ambientValue;
            continue;
        }
        dvec3 normal = transmit ? -sh.normal : sh.normal;
        Spectrum cached;
        if (!beyond && cache_.irradiance(Receiver{sh.point, normal, state.ambientLevel, ctx.time}, surface,
                                         state.weight, coef, ctx, cached)) {
            sum += coef * cached * float(1 / kPi);
            continue;
        }
        int count = state.ambientLevel == 0 ? settings_.ambientDivisions : 1;
        PathState child;
        float boost;
        if (!roulette_.spawn(state, child, coef, !transmit, ctx.rng, boost, beyond, count)) continue;
        child.kind = PathState::Kind::Sampled;
        child.ambientLevel = state.ambientLevel + 1;
        aimingFrom(child, sh.point, normal, count, portals_.active());
        Spectrum throughput;
        carryThroughput(state, child, coef * float(boost / count), throughput);
        Spectrum paths(0.f);
        if (deferring(state, beyond, ctx))
            ctx.bounces->defer(DeferredBounce{sh.point, glm::vec3(normal), surface, scene_.surfaceObject(surface),
                                              float(glm::length(sh.point - state.from)), float(child.weight),
                                              int16_t(child.reflections), int16_t(child.depth)},
                               throughput);
        else
            paths += cosinePaths(sh.point, normal, surface, count, child, ctx);
        if (portals_.active()) paths += portals_.sample(sh.point, normal, surface, count, child, ctx);
        if (patches_.active()) paths += patches_.sample(sh.point, normal, surface, count, child, ctx);
        sum += coef * paths * float(boost / count);
    }
    return sum;
}

// A first bounce hands its continuation to the bounce sink where the run gave one (its path carrying its
// throughput); not from inside closed volumes (antimatter, mists), which a continuation starting afresh would
// not know.
bool SurfaceScattering::deferring(const PathState& state, bool beyond, const PathContext& ctx) const {
    return ctx.bounces && state.throughput && state.ambientLevel == 1 && !beyond && state.clips.count == 0 &&
           state.mists.count == 0;
}

Spectrum SurfaceScattering::cosinePaths(const dvec3& point, const dvec3& normal, const SurfaceId& surface, int count,
                                        const PathState& child, PathContext& ctx) const {
    Frame frame(normal);
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    Spectrum paths(0.f);
    for (int i = 0; i < count; ++i) {
        double u, v;
        sobol2D(i, scramble, u, v);
        paths += tracer_.radiance(Ray{point, frame.toWorld(cosineHemisphere(u, v)), std::numeric_limits<double>::infinity(),
                                      surface},
                                  child, ctx, nullptr);
    }
    return paths;
}

PathState SurfaceScattering::continuationOf(const DeferredBounce& bounce) const {
    PathState state;
    state.kind = PathState::Kind::Sampled;
    state.ambientLevel = 2;
    state.weight = bounce.weight;
    state.reflections = bounce.reflections;
    state.depth = bounce.depth;
    aimingFrom(state, bounce.point, dvec3(bounce.normal), 1, portals_.active());
    return state;
}

}  // namespace brume
