// Radiance along rays: what a ray meets (a surface, a source, media, the sky beyond everything), how the
// hit is shaded, and how sources that sampled rays meet are counted against next-event estimation.
#include "integrator/integrator.h"

#include <cmath>
#include <glm/gtx/component_wise.hpp>


namespace brume {

using namespace integrator_detail;

namespace {

// Sources smaller than this (sr; a cone of 0.05 rad, the sun's is 6.8e-5) that a path meets only through a specular
// bounce after a diffuse one are met by chance: see foundByChance.
constexpr double kChanceSolidAngle = 2e-3;

}  // namespace

Integrator::Integrator(const RenderScene& scene, const RenderSettings& settings, const SurfaceCache* cache,
                       const VolumeCache* volumes)
    : scene_(scene),
      settings_(inBands(settings)),
      seeds_{runSeed(settings)},
      roulette_(settings.maxReflections, settings.minWeight),
      instants_(scene, settings.majorantCell),
      media_(scene, settings_, instants_),
      shading_(scene),
      shadowRays_(scene, shading_, media_),
      lights_(scene, settings_, shading_, media_, shadowRays_),
      portals_(scene, shading_, shadowRays_, settings_.skyPortals),
      patches_(scene, shading_, shadowRays_, lights_, settings_.skyPortals),
      cache_(cache, volumes, scene, settings_, *this, shading_, media_, lights_, portals_, patches_, seeds_,
             instants_.recordWindows(settings.recordLifetime)),
      surfaces_(scene, settings_, lights_, portals_, patches_, cache_, *this, roulette_),
      mediaTransport_(scene, settings_, lights_, cache_, *this, roulette_) {
    const Bounds3& extent = scene.geometry().extent();
    epsilon_ = 1e-7 * (extent.empty() ? 1.0 : glm::length(extent.hi - extent.lo));
    if (settings.time) checkInstants(scene.smoke(), {&*settings.time, 1});
}

// Rays given on input may start exactly on a surface (a sensor on the floor); like Radiance, which ignores
// hits closer than 1e-6, ignore those, but relative to the scene's size and the point's distance from the
// scene's origin (sensor files round their coordinates), and beyond the double rounding of the point's
// coordinates: the same at a site's coordinates as at (0, 0, 0).
double Integrator::primaryTmin(const dvec3& org) const {
    return epsilon_ + 4e-7 * glm::compMax(glm::abs(org - scene_.geometry().origin())) +
           1e-14 * glm::compMax(glm::abs(org));
}

PathContext Integrator::contextFor(const RayQuery& q, WorkItem& item, RayOutputs& outputs) const {
    // Records and media do not carry throughput: they would leave contributions and deferred bounces out.
    if ((item.contributions || item.bounces) && (item.visit || media_.present()))
        throw Error("contributions and shared bounces are not told through the irradiance cache or participating media");
    return PathContext{Random(seedFor(q.index), q.index), item.scratch, q.time, media_.smokeAt(q.time), item.visit,
                       &outputs, item.contributions, item.bounces};
}

namespace {
// The state a query's first ray starts with: where contributions are collected or bounces deferred, a
// throughput of 1.
PathState rootOf(PathState start, const PathContext& ctx, const Spectrum& one) {
    if (ctx.contributions || ctx.bounces) start.throughput = &one;
    return start;
}
}  // namespace

RayRecord Integrator::trace(const RayQuery& q, WorkItem& item, RayTree* tree) const {
    RayOutputs outputs(tree);
    PathContext ctx = contextFor(q, item, outputs);
    RayRecord rec;
    rec.point = q.org;
    Ray ray{q.org, glm::normalize(q.dir)};
    if (q.maxDistance > 0) ray.tmax = q.maxDistance;
    ray.tmin = primaryTmin(q.org);
    const Spectrum one(1.f);
    rec.value = radiance(ray, rootOf(shading_.startingAt(q.org, item.scratch), ctx, one), ctx, nullptr, &rec);
    return rec;
}

RayRecord Integrator::irradiance(const RayQuery& q, WorkItem& item, RayTree* tree) const {
    RayOutputs outputs(tree);
    PathContext ctx = contextFor(q, item, outputs);
    dvec3 n = glm::normalize(q.dir);
    RayRecord rec;
    rec.point = q.org;
    rec.normal = rec.surfaceNormal = n;
    rec.value = sensorIrradiance(q.org + primaryTmin(q.org) * n, n, SurfaceId{}, 0.0, ctx, rec, -n);
    return rec;
}

// Radiance's -i: transparent surfaces (glass, trans, dielectric, void illums) are passed without their
// colour; what the ray then sees is a source (its radiance) or an opaque surface (its irradiance, as a
// white Lambertian sensor). The record names the first surface met, as Radiance's does.
RayRecord Integrator::irradianceAtHit(const RayQuery& q, WorkItem& item, RayTree* tree) const {
    Ray ray{q.org, glm::normalize(q.dir)};
    ray.tmin = primaryTmin(q.org);
    RayOutputs outputs(tree);
    PathContext ctx = contextFor(q, item, outputs);
    RayRecord rec;
    rec.point = q.org;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(ray);
        Shading sh;
        int mat = -1;
        if (hit) {
            sh = shadingAt(ray, *hit, false, scene_.objectFrame(hit->surface));
            mat = shading_.shaderAt(ray, *hit, sh, ctx.rng, item.scratch.patterns);
        }
        if (hit && crossing == 0) {
            RayOutputs::Scope first(outputs, &rec);
            outputs.hit(*hit, sh.normal, scene_.surfaceObject(hit->surface), mat);
        }
        const Emitter* e = mat >= 0 ? scene_.emitter(mat) : nullptr;
        auto isTransparent = [&](int m) {
            const std::string& type = scene_.scene().objects[m].type;
            return type == "glass" || type == "trans" || type == "trans2" || type == "dielectric" || type == "mist";
        };
        // An illum is seen as its alternate material, or not at all.
        bool transparent = hit && (mat < 0 || (e && e->kind == Emitter::Kind::Illum
                                                   ? e->alternate < 0 || isTransparent(e->alternate)
                                                   : isTransparent(mat)));
        if (!hit || (e && !transparent)) {
            const Spectrum one(1.f);
            rec.value = radiance(ray, rootOf(shading_.startingAt(q.org, item.scratch), ctx, one), ctx, nullptr);
            return rec;
        }
        if (!transparent) {
            rec.value = sensorIrradiance(hit->point, sh.normal, hit->surface, hit->t, ctx, rec, ray.dir);
            return rec;
        }
        ray = Ray{hit->point, ray.dir, std::numeric_limits<double>::infinity(), hit->surface};
    }
    return rec;
}

Spectrum Integrator::continueBounce(const DeferredBounce& bounce, const dvec3& dir, double time, double weightScale,
                                    uint64_t index, WorkItem& item) const {
    RayOutputs outputs(nullptr);
    WorkItem told{item.scratch, nullptr, item.contributions};
    PathContext ctx = contextFor(RayQuery{bounce.point, dir, index, time}, told, outputs);
    const Spectrum one(1.f);
    PathState state = surfaces_.continuationOf(bounce);
    state.weight *= weightScale;
    if (ctx.contributions) state.throughput = &one;
    return radiance(Ray{bounce.point, dir, std::numeric_limits<double>::infinity(), bounce.surface}, state, ctx, nullptr);
}

// Irradiance as Radiance computes it for -I and -i: the value of a white Lambertian sensor of reflectance π
// facing n. It stands for a primary ray: in a ray tree, its rays are its children.
Spectrum Integrator::sensorIrradiance(const dvec3& point, const dvec3& n, const SurfaceId& surface, double distance,
                                      PathContext& ctx, RayRecord& rec, const dvec3& dir) const {
    Shading sh{point, n, -n, 1.0, false, false, distance};
    Lobes lobes;
    lobes.diffuse = lobes.ambient = Spectrum(float(kPi));
    RayOutputs& outputs = *ctx.outputs;
    outputs.beginSensor();
    Spectrum value;
    {
        RayOutputs::Scope none(outputs, nullptr);
        const Spectrum one(1.f);
        PathState root = rootOf(shading_.startingAt(point, ctx.scratch), ctx, one);
        root.sensor = true;
        value = surfaces_.shade(sh, lobes, surface, root, ctx, nullptr);
    }
    outputs.endSensor(sh.point, dir, rec, value);
    return value;
}

// The radiance along a ray; with a ray tree to fill, the ray is added after its children.
Spectrum Integrator::radiance(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare,
                              RayRecord* record) const {
    // Most rays: nobody asks for their outputs, nor for their parent's.
    if (!ctx.outputs || (!record && !ctx.outputs->record() && !ctx.outputs->tree()))
        return radianceAlong(ray, state, ctx, sourceShare);
    RayOutputs::Scope scope(*ctx.outputs, record);
    if (!ctx.outputs->tree()) return radianceAlong(ray, state, ctx, sourceShare);
    RayOutputs::TreeRay traced(*ctx.outputs, ray.org, ray.dir);
    Spectrum value = radianceAlong(ray, state, ctx, sourceShare);
    traced.end(value);
    return value;
}

Spectrum Integrator::radianceAlong(const Ray& ray, const PathState& state, PathContext& ctx,
                                   Spectrum* sourceShare) const {
    auto hit = scene_.geometry().intersect(ray);
    if (media_.present()) {
        HomogeneousMedium h = media_.homogeneousAlong(ray, hit ? &*hit : nullptr, state);
        if (!h.clear() || ctx.smoke.smokeAlong(ray, 0, hit ? hit->t : ray.tmax))
            return mediaTransport_.along(ray, hit, h, state, ctx, sourceShare);
    }
    return surfaceRadiance(ray, hit, state, ctx, sourceShare);
}

Spectrum Integrator::surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>& hit, const PathState& state,
                                     PathContext& ctx, Spectrum* sourceShare) const {
    if (!hit) return escaped(ray, state, ctx, sourceShare);
    Shading sh = shadingAt(ray, *hit, scene_.geometry().isFlat(hit->surface), scene_.objectFrame(hit->surface));
    if (state.kind == PathState::Kind::Primary && scene_.varies(hit->surface))
        return blendedHit(ray, *hit, sh, state, ctx, sourceShare);
    int mat = shading_.shaderAt(ray, *hit, sh, ctx.rng, ctx.scratch.patterns);
    return shadeHit(ray, *hit, sh, mat, state, ctx, sourceShare);
}

// A primary ray's value is the answer itself: where a mixture of materials covers the surface, both are
// shaded and blended, as Radiance does, rather than one chosen at random. (Deeper rays choose.) The ray's
// outputs are those of the main material.
Spectrum Integrator::blendedHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const PathState& state,
                                PathContext& ctx, Spectrum* sourceShare) const {
    ModifierChain::Branches branches;
    int n = shading_.blend(ray, hit, ctx.scratch.patterns, branches);
    int main = int(std::max_element(branches.share, branches.share + n) - branches.share);
    RayRecord* record = ctx.outputs ? ctx.outputs->record() : nullptr;
    Spectrum sum(0.f);
    for (int k = 0; k < n; ++k) {
        Shading textured = sh;
        applyTexturing(textured, branches.shader[k].texturing, ray, hit);
        std::optional<RayOutputs::Scope> scope;
        if (ctx.outputs) scope.emplace(*ctx.outputs, k == main ? record : nullptr);
        PathState branch = state;
        Spectrum throughput;
        carryThroughput(state, branch, float(branches.share[k]), throughput);
        sum += shadeHit(ray, hit, textured, branches.shader[k].material, branch, ctx, sourceShare) *
               float(branches.share[k]);
    }
    return sum;
}

// The value of a hit shaded by material (or emitter) `mat`; -1 and cut-away surfaces let the ray go on.
Spectrum Integrator::shadeHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, int mat, const PathState& state,
                              PathContext& ctx, Spectrum* sourceShare) const {
    if (PathState crossed = state; shading_.passes(mat, glm::dot(hit.normal, ray.dir) > 0, crossed))
        return passThrough(ray, hit, crossed, ctx, sourceShare);
    if (RayOutputs* out = ctx.recording()) out->hit(hit, sh.normal, scene_.surfaceObject(hit.surface), mat);
    if (const Emitter* e = scene_.emitter(mat)) return emitterHit(ray, hit, sh, *e, state, ctx, sourceShare);
    return scatterHit(ray, hit, sh, *scene_.material(mat), state, ctx, sourceShare);
}

// The value of a hit on a material.
Spectrum Integrator::scatterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Material& m,
                                const PathState& state, PathContext& ctx, Spectrum* sourceShare) const {
    PatternHit functionHit;
    Shading at = shading_.forMaterial(ray, hit, sh, functionHit, ctx.scratch.patterns);
    Lobes lobes;
    if (!m.scatter(at, lobes)) return passThrough(ray, hit, state, ctx, sourceShare);
    PathState attenuated = state;
    Spectrum throughput;
    carryThroughput(state, attenuated, lobes.incomingAttenuation, throughput);
    return surfaces_.shade(at, lobes, hit.surface, attenuated, ctx, sourceShare) * lobes.incomingAttenuation;
}

Spectrum Integrator::passThrough(const Ray& ray, const SurfaceHit& hit, const PathState& state, PathContext& ctx,
                                 Spectrum* sourceShare) const {
    if (state.depth > kSafetyDepth) return Spectrum(0.f);
    PathState next = state;
    ++next.depth;
    Ray on{hit.point, ray.dir, std::numeric_limits<double>::infinity(), hit.surface};
    RayOutputs* out = ctx.recording();
    RayRecord beyond;
    Spectrum value = radiance(on, next, ctx, sourceShare, out ? &beyond : nullptr);
    if (out) out->passedThrough(beyond, hit.t);
    return value;
}

Spectrum Integrator::escaped(const Ray& ray, const PathState& state, PathContext& ctx, Spectrum* sourceShare) const {
    // A ray with a length limit (a view's aft clipping plane, rtrace's ray length) ends before infinity,
    // where distant sources and skies are: black, as in Radiance.
    if (std::isfinite(ray.tmax)) return Spectrum(0.f);
    // Radiance's order: real sources first, then glows (skies).
    for (bool glows : {false, true}) {
        for (int li : scene_.distantLights()) {
            const Light& light = scene_.lights()[li];
            const Emitter& e = light.emitter();
            if ((e.kind == Emitter::Kind::Glow) != glows || !light.distantContains(ray.dir)) continue;
            auto emitted = [&] {
                Spectrum le = e.emitted(-ray.dir);
                if (light.patterned())
                    le *= shading_.sourcePattern(light, ray.org, -ray.dir, ray.dir, kDistantSourceDistance,
                                                 ctx.scratch.patterns);
                return le;
            };
            if (e.kind == Emitter::Kind::Illum) {
                if (state.viaMirror >= 0) return Spectrum(0.f);  // next-event's, through the mirror's image
                if (state.kind == PathState::Kind::Sampled)
                    return sampledSourceShare(emitted(), li, state, ray, nullptr, ctx, sourceShare);
                continue;
            }
            int modifier = scene_.lightModifier(light);
            if (RayOutputs* out = ctx.recording()) out->distantSource(light.object(), modifier, ray.dir);
            Spectrum le = emitted();
            if (glows) return metSource(le, float(portals_.rayShare(state, ray.dir, ctx.scratch)), modifier, ray, nullptr, state, ctx);
            if (state.viaMirror >= 0) return Spectrum(0.f);  // next-event's, through the mirror's image
            if (state.kind != PathState::Kind::Sampled) {
                if (foundByChance(light, state, ray.org)) return Spectrum(0.f);
                return settings_.directVisible ? metSource(le, 1.f, modifier, ray, nullptr, state, ctx) : Spectrum(0.f);
            }
            return sampledSourceShare(le, li, state, ray, nullptr, ctx, sourceShare);
        }
    }
    return Spectrum(0.f);
}

Spectrum Integrator::emitterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Emitter& e,
                                const PathState& state, PathContext& ctx, Spectrum* sourceShare) const {
    int li = scene_.lightOfSurface(hit.surface);
    bool sampled = state.kind == PathState::Kind::Sampled;
    if (e.kind == Emitter::Kind::Illum) {
        // A sampled ray meeting a window's front finds light that next-event estimation counts (through the
        // mirror's image if a mirror sent it here).
        if (!sh.backside && li >= 0 && state.viaMirror >= 0) return Spectrum(0.f);
        if (sampled && !sh.backside && li >= 0)
            return sampledSourceShare(e.emitted(-ray.dir) * sh.pattern, li, state, ray, &hit, ctx, sourceShare);
        // Otherwise an illum is its alternate material, or nothing at all.
        Shading own = sh;
        const Material* alt = shading_.alternateMaterial(ray, hit, e, own, ctx.rng, ctx.scratch.patterns);
        if (!alt) return passThrough(ray, hit, state, ctx, sourceShare);
        return scatterHit(ray, hit, own, *alt, state, ctx, sourceShare);
    }
    if (sh.backside) {  // emitters radiate from their front only
        if (settings_.materials.backVisible) return Spectrum(0.f);
        return passThrough(ray, hit, state, ctx, sourceShare);
    }
    bool distantGlow = e.kind == Emitter::Kind::Glow && e.glowRadius >= 0 && hit.t > e.glowRadius;
    Spectrum le = e.emitted(-ray.dir) * sh.pattern;
    if (state.viaMirror >= 0 && li >= 0 && e.kind != Emitter::Kind::Glow) return Spectrum(0.f);  // via the image
    int modifier = scene_.surfaceModifier(hit.surface);
    if (!sampled && li >= 0 && foundByChance(scene_.lights()[li], state, ray.org)) return Spectrum(0.f);
    // -dv- hides sources from the rays that would see them, not the direct light sampled rays carry.
    if (!sampled)
        return settings_.directVisible || distantGlow ? metSource(le, 1.f, modifier, ray, &hit, state, ctx) : Spectrum(0.f);
    if (distantGlow) return metSource(le, 1.f, modifier, ray, &hit, state, ctx);
    if (e.kind == Emitter::Kind::Glow && e.glowRadius < 0) return Spectrum(0.f);  // never seen by sampled rays
    if (li < 0) return metSource(le, 1.f, modifier, ray, &hit, state, ctx);  // not sampled as a source: only paths find it
    return sampledSourceShare(le, li, state, ray, &hit, ctx, sourceShare);
}

// Radiance drops every source a path meets through a specular bounce after a diffuse one (a glass pane's
// reflection, a polished floor): next-event estimation at the diffuse point cannot reach it there. Brume counts
// such paths, unbiased, but for sources so small that a diffuse ray finds them through the bounce by rare luck
// only: the sun reflected by a window onto its sill came as one path in millions carrying 10⁴ times the rest,
// and the irradiance cache spread such a record over sensors across the room (58 times their light). Those are
// dropped, as in Radiance.
bool Integrator::foundByChance(const Light& light, const PathState& state, const dvec3& from) const {
    return state.kind == PathState::Kind::Specular && state.ambientLevel > 0 && light.roughSolidAngle(from) < kChanceSolidAngle;
}

// The light `le` of a source (of `modifier`) a ray meets, `share` of which counts: told to the contributions.
Spectrum Integrator::metSource(const Spectrum& le, float share, int modifier, const Ray& ray, const SurfaceHit* hit,
                               const PathState& state, PathContext& ctx) const {
    if (hit) contribute(ctx, state, modifier, ray.org, ray.dir, hit->t, hit->normal, share, le);
    else contribute(ctx, state, modifier, ray.org, ray.dir, std::numeric_limits<double>::infinity(), -ray.dir, share, le);
    return le * share;
}

// A sampled ray that meets a source next-event estimation samples: its multiple-importance share goes to
// the caller, which weighs it by the lobe that sampled the ray (diffuse lobes leave it all to next-event).
Spectrum Integrator::sampledSourceShare(const Spectrum& le, int light, const PathState& state, const Ray& ray,
                                        const SurfaceHit* hit, PathContext& ctx, Spectrum* sourceShare) const {
    if (!sourceShare) return Spectrum(0.f);
    float share = float(lights_.misWeight(scene_.lights()[light], state, ray, hit));
    *sourceShare += le * share;
    metSource(le, share, scene_.lightModifier(scene_.lights()[light]), ray, hit, state, ctx);
    return Spectrum(0.f);
}

// What a ray drawn from a lobe brings back, the sources it meets included (weighted against next-event
// estimation by the power heuristic, see emitterHit).
Spectrum Integrator::sampledRadiance(const dvec3& from, const SurfaceId& surface, const dvec3& dir, double pdf,
                                     const PathState& parent, PathState& child, PathContext& ctx) const {
    lights_.drawnFrom(child, from, pdf, parent);
    Spectrum emission(0.f);
    Spectrum li = radiance(Ray{from, dir, std::numeric_limits<double>::infinity(), surface}, child, ctx, &emission);
    return li + emission;
}

double Integrator::quotedDepthBetween(const dvec3& from, const dvec3& to, double time, QuotedExtinction quoted) const {
    double distance = glm::length(to - from);
    if (!media_.present() || !(distance > 0)) return 0;
    Ray line(from, (to - from) / distance);
    return media_.smokeAt(time).quotedDepth(line, 0, distance, media_.homogeneousAlong(line, nullptr, PathState{}), quoted);
}

double Integrator::quotedExtinctionAt(const dvec3& point, double time, QuotedExtinction quoted) const {
    if (!media_.present()) return 0;
    Ray here(point, dvec3(0, 0, 1));
    return media_.smokeAt(time).quotedExtinction(point, media_.homogeneousAlong(here, nullptr, PathState{}), quoted);
}

double Integrator::dataCoverageBetween(const dvec3& from, const dvec3& to, double time) const {
    double distance = glm::length(to - from);
    if (!media_.present() || !(distance > 0)) return 1;
    return 1 - std::min(1.0, media_.smokeAt(time).uncoveredLength(Ray(from, (to - from) / distance), 0, distance) / distance);
}

}  // namespace brume
