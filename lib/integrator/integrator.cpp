// Radiance along rays: shading at hits, specular and sampled glossy rays, diffuse interreflection by path
// tracing, sources met by rays, Russian roulette. Next-event estimation is in direct_light.cpp.
#include "integrator/integrator.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <glm/gtx/component_wise.hpp>

#include "integrator/path_state.h"
#include "material/ward.h"
#include "sampling/warp.h"
#include "spectrum/rgb_to_spectrum.h"

namespace brume {

using namespace integrator_detail;

Integrator::Integrator(const RenderScene& scene, const RenderSettings& settings,
                       std::shared_ptr<IrradianceCache> cache)
    : scene_(scene), settings_(settings), cache_(std::move(cache)) {
    static std::atomic<uint64_t> instances{0};
    id_ = ++instances;
    runSeed_ = settings.randomSampling
                   ? mixBits(static_cast<uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()))
                   : settings.seed;
    const Bounds3& extent = scene.geometry().extent();
    epsilon_ = 1e-7 * (extent.empty() ? 1.0 : glm::length(extent.hi - extent.lo));
    if (!cache_) cache_ = makeCache(scene, settings);
    const Spectrum& av = settings.ambientValue;
    if (av.size() == 3) settings_.ambientValue = spectrumFromRgb(av[0], av[1], av[2]);
    const HomogeneousMedium& m = settings.medium;
    global_.extinction = spectrumFromRgb(m.extinction[0], m.extinction[1], m.extinction[2]);
    global_.albedo = spectrumFromRgb(m.albedo[0], m.albedo[1], m.albedo[2]);
    global_.g = m.g;
    std::vector<SmokeVolume> smoke;
    for (const SmokeDescription& d : scene.smoke()) smoke.emplace_back(d, settings.time.value_or(0), settings.majorantCell);
    media_ = ParticipatingMedia(std::move(smoke));
    hasMedia_ = !global_.clear() || scene.hasMists() || media_.hasSmoke();
}

Integrator::~Integrator() = default;

// Rays given on input may start exactly on a surface (a sensor on the floor); like Radiance, which ignores
// hits closer than 1e-6, ignore those, but relative to the scene's size and the point's distance from the
// scene's origin (sensor files round their coordinates), and beyond the double rounding of the point's
// coordinates: the same at a site's coordinates as at (0, 0, 0).
double Integrator::primaryTmin(const dvec3& org) const {
    return epsilon_ + 4e-7 * glm::compMax(glm::abs(org - scene_.geometry().origin())) +
           1e-14 * glm::compMax(glm::abs(org));
}

// With -aa > 0 (the irradiance cache) a Radiance user's typical call, -ab of a few bounces, means the light
// of every bounce: paths past the -ab-th go on by Russian roulette, unbiased, one path each (a decided
// difference: Radiance's cache stops there). -av gives them a value instead, and -al+ stops them as Radiance
// does, so that a study can be checked against Radiance's numbers.
bool Integrator::bounceTail() const {
    return settings_.ambientAccuracy > 0 && settings_.ambientBounces > 0 && settings_.ambientValue.isBlack() &&
           !settings_.ambientLimit;
}

uint64_t Integrator::seedFor(uint64_t index) const { return mixBits(runSeed_ ^ mixBits(index + 0x9e3779b97f4a7c15ULL)); }

RayRecord Integrator::trace(const dvec3& org, const dvec3& dir, uint64_t index, double maxDistance,
                            RayTree* tree) const {
    Context ctx{Random(seedFor(index), index), tree, 0, currentVisit()};
    RayRecord rec;
    rec.point = org;
    Ray ray{org, glm::normalize(dir)};
    if (maxDistance > 0) ray.tmax = maxDistance;
    ray.tmin = primaryTmin(org);
    rec.value = radiance(ray, startingAt(org), ctx, &rec, nullptr);
    return rec;
}

RayRecord Integrator::irradiance(const dvec3& p, const dvec3& normal, uint64_t index, RayTree* tree) const {
    Context ctx{Random(seedFor(index), index), tree, 0, currentVisit()};
    dvec3 n = glm::normalize(normal);
    RayRecord rec;
    rec.point = p;
    rec.normal = rec.surfaceNormal = n;
    rec.value = sensorIrradiance(p + primaryTmin(p) * n, n, SurfaceId{}, 0.0, ctx, rec, -n);
    return rec;
}

// Radiance's -i: transparent surfaces (glass, trans, dielectric, void illums) are passed without their
// colour; what the ray then sees is a source (its radiance) or an opaque surface (its irradiance, as a
// white Lambertian sensor). The record names the first surface met, as Radiance's does.
RayRecord Integrator::irradianceAtHit(const dvec3& org, const dvec3& dir, uint64_t index, RayTree* tree) const {
    Ray ray{org, glm::normalize(dir)};
    ray.tmin = primaryTmin(org);
    Context ctx{Random(seedFor(index), index), tree, 0, currentVisit()};
    RayRecord rec;
    rec.point = org;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(ray);
        Shading sh;
        int mat = -1;
        if (hit) {
            sh = shadingAt(ray, *hit, false, scene_.objectFrame(hit->surface));
            mat = shaderAt(ray, *hit, sh, ctx);
        }
        if (hit && crossing == 0) {
            rec.firstLength = rec.effectiveLength = hit->t;
            rec.point = hit->point;
            rec.normal = sh.normal;
            rec.surfaceNormal = hit->normal;
            rec.uv = hit->uv;
            rec.surfaceObject = scene_.surfaceObject(hit->surface);
            rec.modifierObject = mat;
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
            rec.value = radiance(ray, startingAt(org), ctx, nullptr, nullptr);
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

// The state of a path starting at p: in the mists around p. Radiance knows a ray is in a mist only once it
// crosses the boundary; here a probe ray's first crossing of each mist's boundary tells, by the side it
// meets, whether p is inside. The last point asked about is remembered per thread (a picture's eye).
Integrator::PathState Integrator::startingAt(const dvec3& p) const {
    PathState state;
    if (!scene_.hasMists()) return state;
    thread_local uint64_t owner = 0;
    thread_local dvec3 last;
    thread_local InsideVolumes around;
    if (owner == id_ && last == p) {
        state.mists = around;
        return state;
    }
    InsideVolumes met;
    Ray probe{p, glm::normalize(dvec3(0.2113, 0.5774, 0.7887))};  // off the axes, so rarely along a face
    for (int crossing = 0; crossing < 16 * kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(probe);
        if (!hit) break;
        int m = scene_.materialObject(hit->surface);
        if (m >= 0 && scene_.mist(m) && !met.contains(m)) {
            met.enter(m);
            if (glm::dot(hit->normal, probe.dir) > 0) state.mists.enter(m);
        }
        probe = Ray{hit->point, probe.dir, std::numeric_limits<double>::infinity(), hit->surface};
    }
    owner = id_, last = p, around = state.mists;
    return state;
}

// Whether the modifier is cut away by an antimatter volume the ray is in.
bool Integrator::clipped(int modifier, const PathState& state) const {
    for (int i = 0; i < state.clips.count; ++i) {
        const std::vector<int>& cut = *scene_.clippedModifiers(state.clips.objects[i]);
        if (std::find(cut.begin(), cut.end(), modifier) != cut.end()) return true;
    }
    return false;
}

// Antimatter surfaces are invisible; crossing one enters or leaves its volume (it faces outward).
bool Integrator::crossesAntimatter(int mat, bool backside, PathState& state) const {
    if (!scene_.clippedModifiers(mat)) return false;
    if (backside) state.clips.leave(mat);
    else state.clips.enter(mat);
    return true;
}

// A mist's surfaces are not seen: crossing one enters or leaves its volume (it faces outward).
bool Integrator::crossesMist(int mat, bool backside, PathState& state) const {
    if (!scene_.mist(mat)) return false;
    if (backside) state.mists.leave(mat);
    else state.mists.enter(mat);
    return true;
}

// Irradiance as Radiance computes it for -I and -i: the value of a white Lambertian sensor of reflectance π
// facing n. It stands for a primary ray: in a ray tree, its rays are its children.
Spectrum Integrator::sensorIrradiance(const dvec3& point, const dvec3& n, const SurfaceId& surface, double distance,
                                      Context& ctx, RayRecord& rec, const dvec3& dir) const {
    Shading sh{point, n, -n, 1.0, false, false, distance};
    Lobes lobes;
    lobes.diffuse = lobes.ambient = Spectrum(float(kPi));
    ctx.depth = ctx.tree ? 1 : 0;
    Spectrum value = shade(sh, lobes, surface, startingAt(point), ctx, nullptr);
    if (ctx.tree) {
        rec.value = value;
        ctx.tree->rays.push_back({0, sh.point, dir, rec});
    }
    return value;
}

// The radiance along a ray; with a ray tree to fill, the ray is recorded after its children.
Spectrum Integrator::radiance(const Ray& ray, const PathState& state, Context& ctx, RayRecord* record,
                              Spectrum* misEmission) const {
    if (!ctx.tree) return radianceAlong(ray, state, ctx, record, misEmission);
    RayRecord own;
    own.point = ray.org;
    RayRecord* rec = record ? record : &own;
    ++ctx.depth;
    Spectrum value = radianceAlong(ray, state, ctx, rec, misEmission);
    --ctx.depth;
    rec->value = value;
    ctx.tree->rays.push_back({ctx.depth, ray.org, ray.dir, *rec});
    return value;
}

Spectrum Integrator::radianceAlong(const Ray& ray, const PathState& state, Context& ctx, RayRecord* record,
                                   Spectrum* misEmission) const {
    auto hit = scene_.geometry().intersect(ray);
    if (hasMedia_) {
        HomogeneousMedium h = homogeneousAlong(ray, hit ? &*hit : nullptr, state);
        if (!h.clear() || media_.smokeAlong(ray, 0, hit ? hit->t : ray.tmax))
            return throughMedia(ray, hit, h, state, ctx, record, misEmission);
    }
    return surfaceRadiance(ray, hit, state, ctx, record, misEmission);
}

// The radiance of what the ray meets, a surface or, past them all, sources at infinity.
Spectrum Integrator::surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>& hit, const PathState& state,
                                     Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    if (!hit) return escaped(ray, state, record, misEmission);
    Shading sh = shadingAt(ray, *hit, scene_.geometry().isFlat(hit->surface), scene_.objectFrame(hit->surface));
    if (state.kind == PathState::Kind::Primary && scene_.varies(hit->surface))
        return blendedHit(ray, *hit, sh, state, ctx, record, misEmission);
    int mat = shaderAt(ray, *hit, sh, ctx);
    return shadeHit(ray, *hit, sh, mat, state, ctx, record, misEmission);
}

// A primary ray's value is the answer itself: where a mixture of materials covers the surface, both are
// shaded and blended, as Radiance does, rather than one chosen at random. (Deeper rays choose.)
Spectrum Integrator::blendedHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const PathState& state,
                                Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    ModifierChain::Branches branches;
    int n = scene_.modifiers().resolveAll(scene_.surfaceModifier(hit.surface), patternHit(ray, hit), patternEvaluator(),
                                          branches);
    int main = int(std::max_element(branches.share, branches.share + n) - branches.share);
    Spectrum sum(0.f);
    for (int k = 0; k < n; ++k) {
        Shading textured = sh;
        applyTexturing(textured, branches.shader[k].texturing, ray, hit);
        sum += shadeHit(ray, hit, textured, branches.shader[k].material, state, ctx, k == main ? record : nullptr,
                        misEmission) * float(branches.share[k]);
    }
    return sum;
}

// The value of a hit shaded by material (or emitter) `mat`; -1 and cut-away surfaces let the ray go on.
Spectrum Integrator::shadeHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, int mat, const PathState& state,
                              Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    if (mat < 0 || (state.clips.count > 0 && clipped(mat, state)))
        return passThrough(ray, hit, state, ctx, record, misEmission);
    if (PathState crossed = state; crossesAntimatter(mat, glm::dot(hit.normal, ray.dir) > 0, crossed) ||
                                   crossesMist(mat, glm::dot(hit.normal, ray.dir) > 0, crossed))
        return passThrough(ray, hit, crossed, ctx, record, misEmission);
    if (record) {
        record->firstLength = record->effectiveLength = hit.t;
        record->point = hit.point;
        record->normal = sh.normal;
        record->surfaceNormal = hit.normal;
        record->uv = hit.uv;
        record->surfaceObject = scene_.surfaceObject(hit.surface);
        record->modifierObject = mat;
    }
    if (const Emitter* e = scene_.emitter(mat)) return emitterHit(ray, hit, sh, *e, state, ctx, record, misEmission);
    return scatterHit(ray, hit, sh, *scene_.material(mat), state, ctx, record, misEmission);
}

// The value of a hit on a material. Materials with function files evaluate them on the hit as Radiance
// does after its flipsurface: the normal turned toward the ray.
Spectrum Integrator::scatterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Material& m,
                                const PathState& state, Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    PatternHit functionHit = patternHit(ray, hit);
    if (sh.backside) functionHit.normal = -functionHit.normal;
    Shading at = sh;
    at.hit = &functionHit;
    at.evaluator = &patternEvaluator();
    Lobes lobes;
    if (!m.scatter(at, lobes)) return passThrough(ray, hit, state, ctx, record, misEmission);
    return shade(at, lobes, hit.surface, state, ctx, record, misEmission) * lobes.incomingAttenuation;
}

// Each thread's state for evaluating patterns, made on first use for this integrator's scene.
PatternEvaluator& Integrator::patternEvaluator() const {
    thread_local std::unique_ptr<PatternEvaluator> evaluator;
    thread_local uint64_t owner = 0;
    if (owner != id_) {
        evaluator = std::make_unique<PatternEvaluator>(scene_.modifiers());
        owner = id_;
    }
    return *evaluator;
}

// What shades the hit: the surface's material, or what its patterns and mixtures make of it here (then
// `sh` takes their colour and perturbed normal). -1: nothing, the ray goes on.
int Integrator::shaderAt(const Ray& ray, const SurfaceHit& hit, Shading& sh, Context& ctx) const {
    if (!scene_.varies(hit.surface)) return scene_.materialObject(hit.surface);
    Shader s = scene_.modifiers().resolve(scene_.surfaceModifier(hit.surface), patternHit(ray, hit), patternEvaluator(),
                                          ctx.rng.uniform());
    applyTexturing(sh, s.texturing, ray, hit);
    return s.material;
}

// An illum's alternate material, as Radiance's m_light passes rays to it: shaded with that material's own
// modifiers, never the illum's (its pattern is the distribution of the light the illum sends, not a colour
// of the glass). `sh` is made anew for it. Null where the illum has none (void): the ray goes on.
const Material* Integrator::alternateMaterial(const Ray& ray, const SurfaceHit& hit, const Emitter& illum, Shading& sh,
                                              Context& ctx) const {
    if (illum.alternate < 0) return nullptr;
    sh = shadingAt(ray, hit, sh.flat, sh.object);
    int material = illum.alternate;
    if (scene_.modifiers().varies(illum.alternate)) {
        Shader s = scene_.modifiers().resolve(illum.alternate, patternHit(ray, hit), patternEvaluator(),
                                              ctx.rng.uniform());
        applyTexturing(sh, s.texturing, ray, hit);
        material = s.material;
    }
    return material >= 0 ? scene_.material(material) : nullptr;
}

// The hit as patterns see it: in an instance or mesh, in its frame, with the mesh's (u, v).
PatternHit Integrator::patternHit(const Ray& ray, const SurfaceHit& hit) const {
    return PatternHit{hit.point, ray.dir, hit.normal, hit.t, hit.uv.x, hit.uv.y, scene_.objectFrame(hit.surface)};
}

Spectrum Integrator::passThrough(const Ray& ray, const SurfaceHit& hit, const PathState& state, Context& ctx,
                                 RayRecord* record, Spectrum* misEmission) const {
    if (state.depth > kSafetyDepth) return Spectrum(0.f);
    PathState next = state;
    ++next.depth;
    Ray on{hit.point, ray.dir, std::numeric_limits<double>::infinity(), hit.surface};
    RayRecord child;
    Spectrum value = radiance(on, next, ctx, record ? &child : nullptr, misEmission);
    if (record) {
        double first = record->firstLength;
        *record = child;
        record->firstLength += first;
        record->effectiveLength += first;
    }
    return value;
}

double Integrator::misWeightForLight(const Light& light, const PathState& state, const Ray& ray,
                                     const SurfaceHit* hit) const {
    // Distance from where the sampled ray left: it may have crossed clear glass on the way.
    double dist = hit ? glm::length(hit->point - state.from) : std::numeric_limits<double>::infinity();
    dvec3 normal = hit ? hit->normal : dvec3(0);
    double lightDensity = light.pdf(state.from, ray.dir, dist, normal) *
                          light.sampleCount(state.from, state.fromSubdivision, state.fromWeight);
    return powerHeuristic(state.sampledDensity, lightDensity);
}

Spectrum Integrator::escaped(const Ray& ray, const PathState& state, RayRecord* record, Spectrum* misEmission) const {
    // A ray with a length limit (a view's aft clipping plane, rtrace's ray length) ends before infinity,
    // where distant sources and skies are: black, as in Radiance.
    if (std::isfinite(ray.tmax)) return Spectrum(0.f);
    // Radiance's order: real sources first, then glows (skies).
    for (bool glows : {false, true}) {
        for (int li : scene_.distantLights()) {
            const Light& light = scene_.lights()[li];
            const Emitter& e = light.emitter();
            if ((e.kind == Emitter::Kind::Glow) != glows || !light.distantContains(ray.dir)) continue;
            if (e.kind == Emitter::Kind::Illum) {
                if (state.viaMirror >= 0) return Spectrum(0.f);  // next-event's, through the mirror's image
                if (state.kind == PathState::Kind::Sampled) {
                    Spectrum le = e.emitted(-ray.dir);
                    if (light.patterned()) le *= sourcePattern(light, ray.org, -ray.dir, ray.dir, kDistantSourceDistance);
                    return sampledSourceShare(le, li, state, ray, nullptr, misEmission);
                }
                continue;
            }
            if (record) {  // a source at infinity: named, facing the ray, at no distance
                record->surfaceObject = light.object();
                record->modifierObject = scene_.lightModifier(light);
                record->normal = record->surfaceNormal = -ray.dir;
            }
            Spectrum le = e.emitted(-ray.dir);
            if (light.patterned()) le *= sourcePattern(light, ray.org, -ray.dir, ray.dir, kDistantSourceDistance);
            if (glows) return le;
            if (state.viaMirror >= 0) return Spectrum(0.f);  // next-event's, through the mirror's image
            if (state.kind != PathState::Kind::Sampled) return settings_.directVisible ? le : Spectrum(0.f);
            return sampledSourceShare(le, li, state, ray, nullptr, misEmission);
        }
    }
    return Spectrum(0.f);
}

Spectrum Integrator::emitterHit(const Ray& ray, const SurfaceHit& hit, const Shading& sh, const Emitter& e,
                                const PathState& state, Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    int li = scene_.lightOfSurface(hit.surface);
    bool sampled = state.kind == PathState::Kind::Sampled;
    if (e.kind == Emitter::Kind::Illum) {
        // A sampled ray meeting a window's front finds light that next-event estimation counts (through the
        // mirror's image if a mirror sent it here).
        if (!sh.backside && li >= 0 && state.viaMirror >= 0) return Spectrum(0.f);
        if (sampled && !sh.backside && li >= 0)
            return sampledSourceShare(e.emitted(-ray.dir) * sh.pattern, li, state, ray, &hit, misEmission);
        // Otherwise an illum is its alternate material, or nothing at all.
        Shading own = sh;
        const Material* alt = alternateMaterial(ray, hit, e, own, ctx);
        if (!alt) return passThrough(ray, hit, state, ctx, record, misEmission);
        return scatterHit(ray, hit, own, *alt, state, ctx, record, misEmission);
    }
    if (sh.backside) {  // emitters radiate from their front only
        if (settings_.materials.backVisible) return Spectrum(0.f);
        return passThrough(ray, hit, state, ctx, record, misEmission);
    }
    bool distantGlow = e.kind == Emitter::Kind::Glow && e.glowRadius >= 0 && hit.t > e.glowRadius;
    Spectrum le = e.emitted(-ray.dir) * sh.pattern;
    if (state.viaMirror >= 0 && li >= 0 && e.kind != Emitter::Kind::Glow) return Spectrum(0.f);  // via the image
    // -dv- hides sources from the rays that would see them, not the direct light sampled rays carry.
    if (!sampled) return settings_.directVisible || distantGlow ? le : Spectrum(0.f);
    if (distantGlow) return le;
    if (e.kind == Emitter::Kind::Glow && e.glowRadius < 0) return Spectrum(0.f);  // never seen by sampled rays
    if (li < 0) return le;  // not sampled as a source: only paths find it
    return sampledSourceShare(le, li, state, ray, &hit, misEmission);
}

// A sampled ray that meets a source next-event estimation samples: its multiple-importance share goes to
// the caller, which weighs it by the lobe that sampled the ray (diffuse lobes leave it all to next-event).
Spectrum Integrator::sampledSourceShare(const Spectrum& le, int light, const PathState& state, const Ray& ray,
                                        const SurfaceHit* hit, Spectrum* misEmission) const {
    if (misEmission) *misEmission += le * float(misWeightForLight(scene_.lights()[light], state, ray, hit));
    return Spectrum(0.f);
}

bool Integrator::spawn(const PathState& parent, PathState& child, const Spectrum& coef, bool reflection, Context& ctx,
                       float& boost, bool roulette) const {
    double w = std::min(1.0, double(coef.maxValue()));
    child = parent;
    child.weight = parent.weight * w;
    child.reflections = parent.reflections + (reflection ? 1 : 0);
    child.depth = parent.depth + 1;
    child.viaMirror = -1;
    boost = 1.f;
    if (!(child.weight > 0) || child.depth > kSafetyDepth) return false;
    int lr = settings_.maxReflections;
    if (lr > 0) return child.weight >= settings_.minWeight && child.reflections <= lr;
    // Unbiased termination: below -lw by weight, past |lr| reflections by reflectance.
    double survive = 1;
    if (child.weight < settings_.minWeight) survive = child.weight / settings_.minWeight;
    // (Also past kRouletteDepth with -lr 0, so a closed box of perfect mirrors still ends its paths.)
    if (roulette || (lr < 0 && child.reflections > -lr) || child.reflections > kRouletteDepth)
        survive *= std::min(0.95, w);
    if (survive < 1) {
        if (ctx.rng.uniform() >= survive) return false;
        boost = float(1 / survive);
        child.weight /= survive;
    }
    return true;
}

Spectrum Integrator::shade(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                           Context& ctx, RayRecord* record, Spectrum* misEmission) const {
    Spectrum value(0.f);
    double strongest = 0;
    for (int k = 0; k < lobes.deltaCount; ++k) {
        const DeltaLobe& d = lobes.delta[k];
        PathState child;
        float boost;
        if (!spawn(state, child, d.weight, !d.transmits, ctx, boost)) continue;
        // Shadow rays cross straight-through transmissions too, so sources seen through them were already
        // counted at the sampled ray's origin; any other specular bend makes a path only rays can find.
        bool straight = d.transmits && glm::dot(glm::normalize(d.dir), sh.dir) > 1 - 1e-12;
        bool stillSampled = straight && state.kind == PathState::Kind::Sampled;
        if (!stillSampled) child.kind = PathState::Kind::Specular;
        if (state.kind == PathState::Kind::Sampled && !d.transmits && mirrorImagesOn() && scene_.isPlanarMirror(surface))
            child.viaMirror = surface.surface;
        RayRecord childRecord;
        Spectrum share(0.f);
        Spectrum li = radiance(Ray{sh.point, glm::normalize(d.dir), std::numeric_limits<double>::infinity(), surface},
                               child, ctx, record ? &childRecord : nullptr, stillSampled ? &share : nullptr);
        if (misEmission && !share.isBlack()) *misEmission += d.weight * share * boost;
        Spectrum part = d.weight * li * boost;
        value += part;
        if (record) {
            double b = brightness(part);
            if (!d.transmits) {
                record->mirrored += part;
                record->mirroredLength = record->firstLength + childRecord.effectiveLength;
            }
            if (b > strongest) {
                strongest = b;
                record->effectiveLength = record->firstLength + childRecord.effectiveLength;
            }
        }
    }
    bool diffuseOrGlossy = !lobes.diffuse.isBlack() || !lobes.diffuseTrans.isBlack() || !lobes.glossy.isBlack() ||
                           !lobes.glossyTrans.isBlack() || lobes.general;
    if (diffuseOrGlossy) value += direct(sh, lobes, surface, state, ctx);
    if (lobes.sampleGlossy || lobes.sampleGlossyTrans) value += glossy(sh, lobes, surface, state, ctx);
    if (lobes.general && lobes.sampleGeneral) value += general(sh, *lobes.general, surface, state, ctx);
    value += ambient(sh, lobes, surface, state, ctx);
    if (record && brightness(value) > 0 && strongest < 0.5 * brightness(value))
        record->effectiveLength = record->firstLength;
    return value.clampFinite();
}

// One ray per sampled glossy lobe, weighted against next-event estimation where it meets a source.
Spectrum Integrator::glossy(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                            Context& ctx) const {
    Spectrum sum(0.f);
    dvec3 wo = -sh.dir;
    for (bool transmit : {false, true}) {
        if (!(transmit ? lobes.sampleGlossyTrans : lobes.sampleGlossy)) continue;
        const Spectrum& coef = transmit ? lobes.glossyTrans : lobes.glossy;
        double alpha2 = transmit ? lobes.alphaT2 : lobes.alpha2;
        PathState child;
        float boost;
        if (!spawn(state, child, coef, !transmit, ctx, boost)) continue;
        double u = ctx.rng.uniform(), v = ctx.rng.uniform();
        dvec3 wi = transmit ? sampleGaussianTransmission(sh.dir, alpha2, u, v) : sampleWard(wo, sh.normal, alpha2, u, v);
        double cosI = glm::dot(wi, sh.normal);
        if (transmit ? cosI >= 0 : cosI <= 0) continue;  // the sample left the lobe's side: no contribution
        double pdf = transmit ? gaussianTransmissionPdf(sh.dir, wi, alpha2) : wardPdf(wo, wi, sh.normal, alpha2);
        double f = transmit ? gaussianBtdf(sh.dir, wi, alpha2, sh.cosine, -cosI) : wardBrdf(wo, wi, sh.normal, alpha2);
        if (!(pdf > 0)) continue;
        sum += coef * sampledRadiance(sh, surface, wi, pdf, state, child, ctx) * float(f * std::abs(cosI) / pdf * boost);
    }
    return sum;
}

// What a ray sampled with density `pdf` from a lobe at the hit brings back, the sources it meets included
// (weighted against next-event estimation by the power heuristic, see emitterHit).
Spectrum Integrator::sampledRadiance(const Shading& sh, const SurfaceId& surface, const dvec3& dir, double pdf,
                                     const PathState& state, PathState& child, Context& ctx) const {
    child.kind = PathState::Kind::Sampled;
    child.from = sh.point;
    child.fromWeight = state.weight;
    child.fromSubdivision = subdivision(state);
    child.sampledDensity = pdf;
    Spectrum emission(0.f);
    Spectrum li = radiance(Ray{sh.point, dir, std::numeric_limits<double>::infinity(), surface}, child, ctx, nullptr,
                           &emission);
    return li + emission;
}

// One sampled ray for a general lobe, weighted against next-event estimation where it meets a source.
Spectrum Integrator::general(const Shading& sh, const GeneralLobe& lobe, const SurfaceId& surface,
                             const PathState& state, Context& ctx) const {
    double u = ctx.rng.uniform(), v = ctx.rng.uniform();
    auto s = lobe.sample(sh, u, v);
    if (!s || !(s->pdf > 0) || s->weight.isBlack()) return Spectrum(0.f);
    PathState child;
    float boost;
    if (!spawn(state, child, s->weight, !s->transmits, ctx, boost)) return Spectrum(0.f);
    return s->weight * sampledRadiance(sh, surface, s->dir, s->pdf, state, child, ctx) * boost;
}

// Diffuse interreflection on each side with a diffuse coefficient: from the irradiance cache, or by path
// tracing (-ad cosine-distributed, stratified paths at the first bounce and one after it; one where the
// cache has no record yet deeper in a path), for -ab bounces; beyond them Radiance's -av value, or with the cache, paths
// ended by Russian roulette. Sources these paths meet are left out: next-event estimation counted them.
Spectrum Integrator::ambient(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                             Context& ctx) const {
    Spectrum sum(0.f);
    for (bool transmit : {false, true}) {
        const Spectrum& coef = transmit ? lobes.ambientTrans : lobes.ambient;
        if (coef.isBlack()) continue;
        bool beyond = state.ambientLevel >= settings_.ambientBounces;
        if ((beyond && !bounceTail()) || settings_.ambientDivisions <= 0) {
            sum += coef * settings_.ambientValue;
            continue;
        }
        Spectrum cached;
        if (!beyond && cachedAmbient(sh, transmit ? -sh.normal : sh.normal, surface, coef, state, ctx, cached)) {
            sum += coef * cached * float(1 / kPi);
            continue;
        }
        PathState child;
        float boost;
        if (!spawn(state, child, coef, !transmit, ctx, boost, beyond)) continue;
        int count = state.ambientLevel == 0 ? settings_.ambientDivisions : 1;
        child.kind = PathState::Kind::Sampled;
        child.ambientLevel = state.ambientLevel + 1;
        Frame frame(transmit ? -sh.normal : sh.normal);
        uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
        Spectrum paths(0.f);
        for (int i = 0; i < count; ++i) {
            double u, v;
            sobol2D(i, scramble, u, v);
            paths += radiance(Ray{sh.point, frame.toWorld(cosineHemisphere(u, v)),
                                  std::numeric_limits<double>::infinity(), surface},
                              child, ctx, nullptr, nullptr);
        }
        sum += coef * paths * float(boost / count);
    }
    return sum;
}

}  // namespace brume
