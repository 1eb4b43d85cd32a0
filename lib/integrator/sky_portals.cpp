#include "integrator/sky_portals.h"

#include "integrator/contributions.h"
#include "sampling/warp.h"

namespace brume {

using namespace integrator_detail;

namespace {
// Portals smaller than this (sr) seen from a point are left to rays there: their spherical triangles lose
// precision, and little comes through them.
constexpr double kMinSolidAngle = 1e-6;
}  // namespace

SkyPortals::SkyPortals(const RenderScene& scene, const HitShading& shading, const ShadowRays& shadowRays, bool enabled)
    : scene_(scene), shading_(shading), shadowRays_(shadowRays), active_(enabled && !scene.portals().empty()) {}

// In proportion to each portal's projected solid angle: the diffuse light an overcast sky would send through
// it. One portal in view takes every sample, whatever its projection (samples below p's horizon then count
// nothing, as no ray goes there).
bool SkyPortals::choose(const dvec3& p, const dvec3& n, std::vector<PortalChoice>& choices) const {
    const std::vector<Portal>& portals = scene_.portals();
    choices.assign(portals.size(), PortalChoice{});
    int inView = 0;
    for (size_t i = 0; i < portals.size(); ++i) {
        choices[i].view = portals[i].view(p);
        double solidAngle = choices[i].view.solidAngle();
        bool sampled = solidAngle >= kMinSolidAngle && std::isfinite(solidAngle);
        choices[i].probability = sampled ? 1 : 0;
        inView += sampled;
    }
    if (inView < 2) return inView == 1;
    double total = 0;
    for (size_t i = 0; i < portals.size(); ++i) {
        if (choices[i].probability > 0) choices[i].probability = portals[i].projectedSolidAngle(p, n);
        total += choices[i].probability;
    }
    if (!(total > 0)) return false;
    for (PortalChoice& c : choices) c.probability /= total;
    return true;
}

double SkyPortals::densityOf(const dvec3& p, const dvec3& dir, const std::vector<PortalChoice>& choices) const {
    double pdf = 0;
    for (size_t i = 0; i < choices.size(); ++i)
        if (choices[i].probability > 0 && scene_.portals()[i].crossedBy(p, dir))
            pdf += choices[i].probability / choices[i].view.solidAngle();
    return pdf;
}

double SkyPortals::density(const dvec3& p, const dvec3& n, const dvec3& dir, Scratch& scratch) const {
    return active_ && choose(p, n, scratch.portals) ? densityOf(p, dir, scratch.portals) : 0;
}

double SkyPortals::rayShare(const PathState& ray, const dvec3& dir, Scratch& scratch) const {
    if (ray.kind != PathState::Kind::Sampled || ray.skyNormal == dvec3(0)) return 1.0;
    double aimed = density(ray.from, ray.skyNormal, dir, scratch);
    return aimed > 0 ? powerHeuristic(std::max(0.0, glm::dot(ray.skyNormal, dir)) / kPi, ray.aimedPerRay * aimed)
                     : 1.0;
}

Spectrum SkyPortals::skyToward(const dvec3& p, const dvec3& dir, PatternEvaluator& patterns, int& glow) const {
    glow = -1;
    for (bool glows : {false, true})
        for (int li : scene_.distantLights()) {
            const Light& light = scene_.lights()[li];
            if ((light.emitter().kind == Emitter::Kind::Glow) != glows || !light.distantContains(dir)) continue;
            if (!glows) return Spectrum(0.f);
            glow = li;
            Spectrum le = light.emitter().emitted(-dir);
            if (light.patterned()) le *= shading_.sourcePattern(light, p, -dir, dir, kDistantSourceDistance, patterns);
            return le;
        }
    return Spectrum(0.f);
}

// u picks a portal by its probability, then is reused within it: strata stay strata.
dvec3 SkyPortals::aimAt(const std::vector<PortalChoice>& choices, double u, double v, double& distance) {
    size_t i = 0;
    double below = 0;
    for (size_t j = 0; j < choices.size(); ++j) {
        if (choices[j].probability <= 0) continue;
        i = j;
        if (u < below + choices[j].probability) break;
        below += choices[j].probability;
    }
    return choices[i].view.sample(std::clamp((u - below) / choices[i].probability, 0.0, 1.0), v, distance);
}

std::optional<dvec3> SkyPortals::aim(const dvec3& p, const dvec3& n, double u, double v, Scratch& scratch) const {
    if (!active_ || !choose(p, n, scratch.portals)) return std::nullopt;
    double distance;
    return aimAt(scratch.portals, u, v, distance);
}

Spectrum SkyPortals::sample(const dvec3& p, const dvec3& n, const SurfaceId& surface, int rays, const PathState& state,
                            PathContext& ctx, std::vector<AimedSample>* aimed) const {
    std::vector<PortalChoice>& choices = ctx.scratch.portals;
    if (!choose(p, n, choices)) return Spectrum(0.f);
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    Spectrum sum(0.f);
    const int count = aimedCount(rays);
    const double perRay = double(count) / rays;
    for (int k = 0; k < count; ++k) {
        double u, v;
        sobol2D(k, scramble, u, v);
        double distance;
        dvec3 dir = aimAt(choices, u, v, distance);
        double cosine = glm::dot(n, dir);
        if (!(cosine > 0)) continue;
        double pdf = densityOf(p, dir, choices);
        if (!(pdf > 0)) continue;
        PathState crossing = state;
        Spectrum t = shadowRays_.toSurface(Ray{p, dir, std::numeric_limits<double>::infinity(), surface}, SurfaceId{},
                                           true, Emitter::Kind::Glow, crossing, ctx, nullptr);
        if (t.isBlack()) continue;
        int glow;
        Spectrum le = skyToward(p, dir, ctx.scratch.patterns, glow);
        if (le.isBlack()) continue;
        float weight = float(powerHeuristic(perRay * pdf, cosine / kPi) * cosine / (kPi * pdf * perRay));
        Spectrum part = le * t * weight;
        sum += part;
        if (ctx.contributions)
            contribute(ctx, state, scene_.lightModifier(scene_.lights()[glow]), p, dir,
                       std::numeric_limits<double>::infinity(), -dir, t * weight, le);
        if (aimed) aimed->push_back({dir, part * float(kPi / rays), distance});
    }
    return sum;
}

}  // namespace brume
