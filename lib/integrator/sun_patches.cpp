#include "integrator/sun_patches.h"

#include "integrator/contributions.h"
#include "sampling/warp.h"

namespace brume {

using namespace integrator_detail;

namespace {
constexpr int kMaxPanes = 16;  // portals a beam may cross one after another (double glazing is two)
}  // namespace

SunPatches::SunPatches(const RenderScene& scene, const HitShading& shading, const ShadowRays& shadowRays,
                       const LightSampler& lights, bool enabled)
    : scene_(scene), shading_(shading), shadowRays_(shadowRays), lights_(lights) {
    if (!enabled || scene.portals().empty()) return;
    const double maxSolidAngle = 2 * kPi * (1 - std::cos(kMaxAngle / 2));
    for (int li : scene.distantLights()) {
        const Light& light = scene.lights()[li];
        const Emitter& e = light.emitter();
        if (e.kind != Emitter::Kind::Light || e.radiance.isBlack() || light.roughSolidAngle(dvec3(0)) > maxSolidAngle)
            continue;
        Beam beam{li, -light.direction(), 0, {}};
        for (const Portal& portal : scene.portals()) {
            beam.crossSection += portal.area() * std::abs(glm::dot(portal.polygon().normal, beam.travel));
            beam.cdf.push_back(beam.crossSection);
        }
        if (!(beam.crossSection > 0)) continue;
        for (double& c : beam.cdf) c /= beam.crossSection;
        beams_.push_back(std::move(beam));
    }
}

const SunPatches::Beam* SunPatches::beamOf(int light) const {
    for (const Beam& b : beams_)
        if (b.light == light) return &b;
    return nullptr;
}

bool SunPatches::isPortal(const SurfaceId& id) const {
    for (const Portal& p : scene_.portals())
        if (p.surface() == id) return true;
    return false;
}

std::optional<SurfaceHit> SunPatches::land(const Beam& beam, double u, double v) const {
    const Portal& portal = scene_.portals()[pickAndReuse(beam.cdf, u)];
    if (!(std::abs(glm::dot(portal.polygon().normal, beam.travel)) > 0)) return std::nullopt;  // edge-on: no beam
    Ray ray(portal.pointAt(u, v), beam.travel, std::numeric_limits<double>::infinity(), portal.surface());
    for (int pane = 0; pane < kMaxPanes; ++pane) {
        auto hit = scene_.geometry().intersect(ray);
        if (!hit || !isPortal(hit->surface)) return hit;
        ray.org = hit->point;
        ray.leaving = hit->surface;
    }
    return std::nullopt;
}

int SunPatches::portalsBefore(const Beam& beam, const dvec3& point, const SurfaceId& surface) const {
    Ray ray(point, -beam.travel, std::numeric_limits<double>::infinity(), surface);
    int crossed = 0;
    for (int pane = 0; pane < kMaxPanes; ++pane) {
        auto hit = scene_.geometry().intersect(ray);
        if (!hit || !isPortal(hit->surface)) break;
        ++crossed;
        ray.org = hit->point;
        ray.leaving = hit->surface;
    }
    return crossed;
}

// Uniform over the beam's cross-section, through each portal crossed: per unit area of a surface of this
// normal, |cos| to the beam over the cross-section.
double SunPatches::density(const Beam& beam, int portals, const dvec3& normal) const {
    return portals * std::abs(glm::dot(normal, beam.travel)) / beam.crossSection;
}

std::optional<Spectrum> SunPatches::connected(const Beam& beam, const SurfaceHit& at, const Ray& connection,
                                              const Spectrum& t, double cosX, double perRay, const PathState& state,
                                              PathContext& ctx) const {
    Shading sh = shadingAt(connection, at, scene_.geometry().isFlat(at.surface), scene_.objectFrame(at.surface));
    int mat = shading_.shaderAt(connection, at, sh, ctx.rng, ctx.scratch.patterns);
    const Material* material = mat >= 0 && !scene_.emitter(mat) ? scene_.material(mat) : nullptr;
    if (!material) return std::nullopt;
    PatternHit functionHit;
    Shading asSeen = shading_.forMaterial(connection, at, sh, functionHit, ctx.scratch.patterns);
    Lobes lobes;
    if (!material->scatter(asSeen, lobes)) return std::nullopt;
    Scatterer patch(asSeen, lobes);
    if (!patch.onlyLambertian()) return std::nullopt;
    double distance = at.t, cosPatch = std::abs(glm::dot(at.normal, connection.dir));
    int portals = portalsBefore(beam, at.point, at.surface);
    double pdf = density(beam, portals, at.normal) * distance * distance / cosPatch;
    // The weight as the ray's share at the patch computes it (rayShare), from the shading normal.
    double weighed = density(beam, portals, sh.normal) * distance * distance / std::abs(glm::dot(sh.normal, connection.dir));
    if (!(pdf > 0) || !(weighed > 0)) return std::nullopt;
    float weight = float(powerHeuristic(perRay * weighed, cosX / kPi) * cosX / (kPi * pdf * perRay));
    PathState there = state;
    ++there.depth;
    Spectrum throughput;
    if (state.throughput) carryThroughput(state, there, lobes.incomingAttenuation * t * weight, throughput);
    Spectrum le = lights_.fromSource(scene_.lights()[beam.light], patch, at.surface, there, ctx) * lobes.incomingAttenuation;
    if (le.isBlack()) return std::nullopt;
    return le * t * weight;
}

Spectrum SunPatches::sample(const dvec3& x, const dvec3& n, const SurfaceId& surface, int rays, const PathState& state,
                            PathContext& ctx, std::vector<AimedSample>* aimed) const {
    Spectrum sum(0.f);
    const int count = aimedCount(rays);
    const double perRay = double(count) / rays;
    for (const Beam& beam : beams_) {
        uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
        for (int k = 0; k < count; ++k) {
            double u, v;
            sobol2D(k, scramble, u, v);
            std::optional<SurfaceHit> patch = land(beam, u, v);
            if (!patch) continue;
            dvec3 toPatch = patch->point - x;
            double distance = glm::length(toPatch);
            dvec3 dir = toPatch / distance;
            double cosX = glm::dot(n, dir), cosPatch = std::abs(glm::dot(patch->normal, dir));
            if (!(cosX > 0) || !(cosPatch > 0)) continue;
            Ray connection(x, dir, std::numeric_limits<double>::infinity(), surface);
            PathState crossing = state;
            SurfaceHit reached;
            Spectrum t = shadowRays_.toSurface(connection, patch->surface, false, Emitter::Kind::Light, crossing, ctx,
                                               &reached);
            if (t.isBlack() || std::abs(reached.t - distance) > 1e-6 * distance) continue;
            patch->t = distance;
            std::optional<Spectrum> part = connected(beam, *patch, connection, t, cosX, perRay, crossing, ctx);
            if (!part) continue;
            sum += *part;
            if (aimed) aimed->push_back({dir, *part * float(kPi / rays), distance});
        }
    }
    return sum;
}

double SunPatches::rayShare(const Light& light, const Scatterer& at, const SurfaceId& surface, const PathState& state,
                            PathContext&) const {
    if (state.kind != PathState::Kind::Sampled || state.skyNormal == dvec3(0) || !at.surface() || !at.onlyLambertian())
        return 1;
    const Beam* beam = beamOf(int(&light - scene_.lights().data()));
    if (!beam) return 1;
    dvec3 toPatch = at.point() - state.from;
    double distance = glm::length(toPatch);
    dvec3 dir = toPatch / distance;
    double cosX = glm::dot(state.skyNormal, dir), cosPatch = std::abs(glm::dot(at.surface()->normal, dir));
    int portals = cosX > 0 && cosPatch > 0 ? portalsBefore(*beam, at.point(), surface) : 0;
    if (portals == 0) return 1;
    double weighed = density(*beam, portals, at.surface()->normal) * distance * distance / cosPatch;
    return powerHeuristic(cosX / kPi, state.aimedPerRay * weighed);
}

std::optional<SurfaceHit> SunPatches::land(int light, double u, double v) const {
    const Beam* beam = beamOf(light);
    return beam ? land(*beam, u, v) : std::nullopt;
}

double SunPatches::areaDensity(int light, const dvec3& point, const SurfaceId& surface, const dvec3& normal) const {
    const Beam* beam = beamOf(light);
    return beam ? density(*beam, portalsBefore(*beam, point, surface), normal) : 0;
}

}  // namespace brume
