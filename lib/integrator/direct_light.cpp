// Next-event estimation: light reaching a shading point straight from the sources, or through their images
// in flat mirrors, along shadow rays that cross clear glass and antimatter.
#include <cmath>

#include "integrator/integrator.h"
#include "integrator/path_state.h"
#include "material/ward.h"
#include "sampling/random.h"

namespace brume {

using namespace integrator_detail;

// Where a primary ray lands (or at a sensor), the value is the answer itself and nothing averages its
// noise: twice the shadow rays per axis, and diffuse light in closed form. Deeper in a path many paths
// average, and cheaper estimates win.
// With -ab, the shadow rays there grow with √-ad, so that penumbrae get as smooth as the interreflected
// light the -ad paths estimate.
double Integrator::subdivision(const PathState& state) const {
    if (state.depth > 0) return settings_.sourceSubdivision;
    double paths = settings_.ambientBounces > 0 ? std::max(settings_.ambientDivisions, 0) : 0;
    return settings_.sourceSubdivision / std::max(2.0, std::sqrt(paths) / 8);
}

bool Integrator::exactDirect(const PathState& state) const { return state.depth == 0; }

// Radiance's -dt skips the shadow tests of sources whose share of the unoccluded light is below the
// threshold and guesses their visibility, which is biased. Here such sources get fewer shadow rays instead,
// in proportion to their share, down to one: the count depends only on the point, never on what the rays
// find, so the estimate stays unbiased and only its noise grows, where it matters little.
int Integrator::thresholdedCount(int count, double share) const {
    double threshold = settings_.directThreshold;
    if (!(threshold > 0) || share >= threshold) return count;
    return std::max(1, int(std::ceil(count * share / threshold)));
}

// Whether next-event estimation samples the light from a point of `surface` (not the source's own surface).
bool Integrator::samplesSource(const Light& light, const SurfaceId& surface) const {
    return light.emitter().isDirectSource() && !(surface && light.surface() == surface);
}

// Every source sample. Diffuse lobes take their source light from here alone, as in Radiance (a few
// stratified shadow rays beat thousands of diffuse rays that rarely find a small source); glossy lobes
// that are also sampled by rays share it with them by the power heuristic.
Spectrum Integrator::direct(const Shading& sh, const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                            Context& ctx) const {
    const std::vector<Light>& lights = scene_.lights();
    if (state.ambientLevel > 0 && !lobes.sampleGlossy && !lobes.sampleGlossyTrans && !(lobes.general && lobes.sampleGeneral))
        if (auto one = oneSourceOf(sh, lobes, surface, state, ctx)) return *one;
    // Diffuse light of uniform sources: their unoccluded value in closed form (see directFrom), and how
    // bright it is in all, for -dt. A scratch per thread, so that shading allocates nothing.
    thread_local std::vector<double> closedForm;
    closedForm.assign(lights.size(), -1.0);
    double total = 0;
    if (exactDirect(state) && !lobes.diffuse.isBlack() && !lobes.fresnelDiffuse)
        for (size_t i = 0; i < lights.size(); ++i) {
            if (!samplesSource(lights[i], surface)) continue;
            closedForm[i] = lights[i].unoccludedIrradiance(sh.point, sh.normal);
            total += std::max(0.0, closedForm[i]) * brightness(lights[i].emitter().radiance);
        }
    Spectrum sum(0.f);
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!samplesSource(lights[i], surface)) continue;
        double share = closedForm[i] > 0 && total > 0 ? closedForm[i] * brightness(lights[i].emitter().radiance) / total : 1.0;
        sum += directFrom(lights[i], closedForm[i], share, sh, lobes, surface, state, ctx);
    }
    if (mirrorImagesOn()) sum += directViaMirrors(sh, lobes, surface, state, ctx);
    return sum;
}

// Past a diffuse bounce, the points a path shades are averaged many at a time (a record's hemisphere, a
// pixel's paths): there one source stands for all of them, so a point costs one source's shadow rays however
// many sources there are. It is chosen half in proportion to a rough guess of its light, half uniformly: the
// guess knows nothing of what is in the way, and where it is wrong (the sun, 200 times brighter than a
// window it shines through, guessed at a wall it cannot reach) a source chosen by it alone would come
// rarely and with a huge weight; so no source's weight exceeds twice the number of sources. Only where no
// lobe is also sampled by rays (their weights against sources assume every source sampled). Nullopt: fewer
// than two sources to choose from.
std::optional<Spectrum> Integrator::oneSourceOf(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                                const PathState& state, Context& ctx) const {
    const std::vector<Light>& lights = scene_.lights();
    thread_local std::vector<double> guess;
    guess.assign(lights.size(), 0.0);
    double total = 0;
    int candidates = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        if (!samplesSource(light, surface)) continue;
        guess[i] = light.roughSolidAngle(sh.point) * std::max(1e-30f, brightness(light.emitter().radiance));
        total += guess[i];
        candidates += guess[i] > 0;
    }
    if (candidates < 2 || !(total > 0)) return std::nullopt;
    auto probability = [&](size_t i) { return 0.5 * guess[i] / total + 0.5 / candidates; };
    double u = ctx.rng.uniform();
    size_t chosen = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (guess[i] <= 0) continue;
        chosen = i;
        if ((u -= probability(i)) < 0) break;
    }
    Spectrum value = directFrom(lights[chosen], -1, 1.0, sh, lobes, surface, state, ctx) * float(1 / probability(chosen));
    if (mirrorImagesOn()) value += directViaMirrors(sh, lobes, surface, state, ctx);
    return value;
}

// One source's light. With `closedForm` ≥ 0, the diffuse part is that unoccluded value less what the
// shadow rays find blocked (a control variate): exact where nothing is in the way, noisy only in shadows.
Spectrum Integrator::directFrom(const Light& light, double closedForm, double share, const Shading& sh,
                                const Lobes& lobes, const SurfaceId& surface, const PathState& state,
                                Context& ctx) const {
    const Emitter& e = light.emitter();
    Spectrum sum(0.f);
    Spectrum blocked(0.f);  // estimate of the irradiance the closed form counts but obstacles stop
    bool anyThrough = false;  // some controlled shadow ray got through
    // Multiple importance weights take the count rays sampled by lobes assume (misWeightForLight): any
    // weights that sum to one keep the estimate unbiased.
    int nominal = light.sampleCount(sh.point, subdivision(state), state.weight);
    int count = thresholdedCount(nominal, share);
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    if (e.radiance.isBlack()) return sum;
    LightView view = light.view(sh.point);
    Spectrum scratch;  // the radiance of patterned and focused sources (see sourceRadiance)
    bool record = ctx.tree && ctx.tree->withShadowRays;
    for (int k = 0; k < count; ++k) {
        double u, v;
        sobol2D(k, scramble, u, v);
        auto s = light.sample(view, u, v);
        if (!s) continue;
        if (e.kind == Emitter::Kind::Glow && s->distance > e.glowRadius) continue;
        double cosL = glm::dot(sh.normal, s->dir);
        bool controlled = closedForm >= 0 && cosL > 0;
        Spectrum f = response(sh, lobes, s->dir, s->pdf * nominal, !controlled);
        if (f.isBlack() && !controlled) continue;
        Ray shadow{sh.point, s->dir, std::numeric_limits<double>::infinity(), surface};
        float weight = float(1 / (s->pdf * count));
        Occlusion seen = scene_.geometry().occlusion(shadow, light.surface(), s->distance, scene_);
        if (seen == Occlusion::Unsure || (seen == Occlusion::Clear && attenuates(shadow, s->distance, state))) {
            const Spectrum& le = sourceRadiance(light, *s, sh.point, scratch);
            Spectrum t = seen == Occlusion::Unsure ? shadowTransmittance(shadow, light, state, ctx)
                                                   : clearTransmittance(shadow, s->distance, state, ctx);
            if (record) recordShadowRay(ctx, sh.point, *s, light, le * t);
            sum.addProduct(f * t, le, weight);
            if (controlled) {
                blocked += (Spectrum(1.f) - t) * float(cosL * weight);
                anyThrough = anyThrough || !t.isBlack();
            }
            continue;
        }
        // Transmission 1 or 0 in every channel: the same sums as above without a spectrum per ray, and the
        // source's pattern evaluated only where it is seen.
        bool clear = seen == Occlusion::Clear;
        if (record) recordShadowRay(ctx, sh.point, *s, light, sourceRadiance(light, *s, sh.point, scratch) * float(clear));
        if (clear && !f.isBlack()) sum.addProduct(f, sourceRadiance(light, *s, sh.point, scratch), weight);
        if (controlled && !clear) blocked += float(cosL * weight);
        anyThrough = anyThrough || (controlled && clear);
    }
    if (closedForm >= 0 && anyThrough) {
        // Every ray blocked means shadow: 0, not the closed form less a noisy estimate of itself (for the
        // sun, that noise alone would be a visible glow in every shadow). In penumbrae the estimate of
        // what is blocked can still exceed the whole: never below 0.
        Spectrum unblocked = Spectrum(float(closedForm)) - blocked;
        for (int c = 0; c < unblocked.size(); ++c) unblocked[c] = std::max(0.f, unblocked[c]);
        sum += lobes.diffuse * e.radiance * unblocked * float(1 / kPi);
    }
    return sum;
}

// The lobes' response f·|cos| to light from direction l. A glossy lobe that is also sampled by rays takes
// its share against the source's sampling density (power heuristic); lightDensity 0 gives every lobe
// all of it (sources no ray will count).
Spectrum Integrator::response(const Shading& sh, const Lobes& lobes, const dvec3& l, double lightDensity,
                              bool withDiffuse) const {
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

// The radiance a source sample sends toward `from`: the emitter's own, or, with Radiance's spotlight focus (a
// spotlight acts as if it were its focal distance farther behind its surface) and the source's pattern,
// `scratch` made so, without a spectrum per sample.
const Spectrum& Integrator::sourceRadiance(const Light& light, const LightSample& s, const dvec3& from,
                                           Spectrum& scratch) const {
    const Emitter& e = light.emitter();
    bool finite = std::isfinite(s.distance);
    bool focused = e.kind == Emitter::Kind::Spotlight && finite;
    if (!focused && !light.patterned()) return e.radiance;
    scratch = e.radiance;
    if (focused)
        scratch *= float(s.distance * s.distance / ((s.distance + e.spotFocus) * (s.distance + e.spotFocus)));
    if (light.patterned())
        scratch *= sourcePattern(light, finite ? from + s.distance * s.dir : from, s.normal, s.dir,
                                 finite ? s.distance : kDistantSourceDistance);
    return scratch;
}

// The colour of a source's patterns where a ray in direction `dir` meets it (e.g. a luminaire's intensity
// distribution from ies2rad, or a sky's luminance distribution).
Spectrum Integrator::sourcePattern(const Light& light, const dvec3& point, const dvec3& normal, const dvec3& dir,
                                   double distance) const {
    PatternHit hit{point, dir, normal, distance};
    if (!light.isDistant()) hit.object = scene_.objectFrame(light.surface());
    return scene_.modifiers().resolve(scene_.lightModifier(light), hit, patternEvaluator(), 0.5).texturing.color;
}

void Integrator::recordShadowRay(Context& ctx, const dvec3& from, const LightSample& s, const Light& light,
                                 const Spectrum& value) const {
    RayRecord shadow;
    shadow.value = value;
    shadow.firstLength = shadow.effectiveLength = s.distance;
    shadow.point = from + (std::isfinite(s.distance) ? s.distance : 0.0) * s.dir;
    shadow.surfaceObject = light.object();
    shadow.modifierObject = scene_.lightModifier(light);
    ctx.tree->rays.push_back({ctx.depth, from, s.dir, shadow});
}

// Sources seen in flat mirrors (Radiance's virtual sources, one relay): each source is sampled as seen
// from the shading point's mirror image, and the shadow ray goes to the mirror and on to the source.
// Sampled rays that take the same route count nothing (see emitterHit), so each path counts once.
Spectrum Integrator::directViaMirrors(const Shading& sh, const Lobes& lobes, const SurfaceId& surface,
                                      const PathState& state, Context& ctx) const {
    Spectrum sum(0.f);
    Spectrum scratch;
    for (const PlanarMirror& mirror : scene_.planarMirrors()) {
        double height = glm::dot(mirror.normal, sh.point) - mirror.offset;
        if (mirror.surface == surface || height <= 0) continue;  // mirrors reflect from their front only
        dvec3 image = sh.point - 2 * height * mirror.normal;
        for (const Light& light : scene_.lights()) {
            const Emitter& e = light.emitter();
            // Glows, lit only within a radius, are left to rays.
            if (!e.isDirectSource() || e.kind == Emitter::Kind::Glow ||
                (light.isDistant() && glm::dot(light.direction(), mirror.normal) <= 0))
                continue;
            int count = light.sampleCount(image, subdivision(state), state.weight);
            uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
            LightView view = light.view(image);
            for (int k = 0; k < count; ++k) {
                double u, v;
                sobol2D(k, scramble, u, v);
                auto s = light.sample(view, u, v);
                if (!s || e.radiance.isBlack()) continue;
                dvec3 d = s->dir - 2 * glm::dot(s->dir, mirror.normal) * mirror.normal;  // toward the image
                double toMirror = -height / glm::dot(mirror.normal, d);
                if (!(toMirror > 0) || toMirror >= s->distance) continue;
                Spectrum f = response(sh, lobes, d, 0);
                if (f.isBlack()) continue;
                PathState crossing = state;
                SurfaceHit onMirror;
                Spectrum t = transmittance(Ray{sh.point, d, std::numeric_limits<double>::infinity(), surface},
                                           mirror.surface, false, e.kind, crossing, ctx, &onMirror);
                if (t.isBlack()) continue;
                Ray onward{onMirror.point, s->dir, std::numeric_limits<double>::infinity(), mirror.surface};
                // The source's sample lies along the onward ray only if the way to the mirror went straight.
                Occlusion seen = scene_.shadowsBend() ? Occlusion::Unsure
                                                      : scene_.geometry().occlusion(onward, light.surface(),
                                                                                    s->distance - toMirror, scene_);
                if (seen == Occlusion::Blocked) continue;
                if (seen == Occlusion::Unsure) t *= shadowTransmittance(onward, light, crossing, ctx);
                else if (hasMedia_) t *= clearTransmittance(onward, s->distance - toMirror, crossing, ctx);
                if (!t.isBlack())
                    sum += f * sourceRadiance(light, *s, image, scratch) * mirror.reflectance * t * float(1 / (s->pdf * count));
            }
        }
    }
    return sum;
}

// What reaches the source along a shadow ray: 1 if nothing is in the way, the product of glass and
// clear-trans transmissions it crosses, 0 if something opaque or another emitter blocks it.
Spectrum Integrator::shadowTransmittance(const Ray& ray, const Light& light, PathState state, Context& ctx) const {
    return transmittance(ray, light.surface(), light.isDistant(), light.emitter().kind, state, ctx, nullptr);
}

// Along a shadow ray to surface `target` (or, for a source at infinity, out of the scene): the
// transmission of what it crosses, black if blocked. `reached` receives the hit on the target.
Spectrum Integrator::transmittance(Ray ray, const SurfaceId& target, bool toInfinity, Emitter::Kind targetKind,
                                   PathState& state, Context& ctx, SurfaceHit* reached) const {
    Spectrum t(1.f);
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        auto hit = scene_.geometry().intersect(ray);
        if (hasMedia_) {
            t *= mediaTransmittance(ray, 0, hit ? hit->t : ray.tmax,
                                    homogeneousAlong(ray, hit ? &*hit : nullptr, state), ctx);
            if (t.isBlack()) return t;
        }
        if (!hit) return toInfinity ? t : Spectrum(0.f);
        // The source itself: its pattern is the caller's (sourceRadiance), only its material matters here,
        // so the shading most shadow rays end on is skipped.
        bool onTarget = hit->surface == target;
        Shading sh;
        if (!onTarget) sh = shadingAt(ray, *hit, false, scene_.objectFrame(hit->surface));
        int mat = onTarget ? scene_.materialObject(target) : shaderAt(ray, *hit, sh, ctx);
        bool cut = mat < 0 || (state.clips.count > 0 && clipped(mat, state)) ||
                   crossesAntimatter(mat, glm::dot(hit->normal, ray.dir) > 0, state) ||
                   crossesMist(mat, glm::dot(hit->normal, ray.dir) > 0, state);
        if (cut) {
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
        const Material* m = e ? alternateMaterial(ray, *hit, *e, sh, ctx) : scene_.material(mat);
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
