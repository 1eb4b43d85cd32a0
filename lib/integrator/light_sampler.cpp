#include "integrator/light_sampler.h"

#include <algorithm>
#include <cmath>

#include "integrator/contributions.h"

namespace brume {

using namespace integrator_detail;

// Where a primary ray lands (or at a sensor), the value is the answer itself and nothing averages its
// noise: twice the shadow rays per axis, and diffuse light in closed form. Deeper in a path many paths
// average, and cheaper estimates win.
// With -ab, the shadow rays there grow with √-ad, so that penumbrae get as smooth as the interreflected
// light the -ad paths estimate.
double LightSampler::subdivision(const PathState& state) const {
    if (state.depth > 0) return settings_.sourceSubdivision;
    double paths = settings_.ambientBounces > 0 ? std::max(settings_.ambientDivisions, 0) : 0;
    return settings_.sourceSubdivision / std::max(2.0, std::sqrt(paths) / 8);
}

namespace {
constexpr int kSensorRays = 64;
}  // namespace

// A sensor's value is its own answer: a small source (the sun, 0.5°) would get one shadow ray by -ds, and a
// sensor on the edge of its shadow would read all of it or none (a sensor at the sunlit patch's edge under a low
// December sun: 10 % of its light in two runs of five). 64 stratified rays, shared among the sources, put such
// a sensor within a few per cent and cost it little next to its -ad paths; thousands of suns, one an hour
// (rcontrib's direct-sun matrix), keep one ray each. (A sensor's lobe is diffuse: no ray shares the sources
// with these samples, so no multiple-importance weight depends on their number.)
int LightSampler::sensorRaysPerSource(const RenderScene& scene) {
    long sources = std::count_if(scene.lights().begin(), scene.lights().end(),
                                 [](const Light& l) { return l.emitter().isDirectSource(); });
    return std::max(1L, kSensorRays / std::max(1L, sources));
}

// Radiance's -dt skips the shadow tests of sources whose share of the unoccluded light is below the
// threshold and guesses their visibility, which is biased. Here such sources get fewer shadow rays instead,
// in proportion to their share, down to one: the count depends only on the point, never on what the rays
// find, so the estimate stays unbiased and only its noise grows, where it matters little.
int LightSampler::thresholdedCount(int count, double share) const {
    double threshold = settings_.directThreshold;
    if (!(threshold > 0) || share >= threshold) return count;
    return std::max(1, int(std::ceil(count * share / threshold)));
}

// Whether next-event estimation samples the light from a point of `surface` (not the source's own surface).
bool LightSampler::samplesSource(const Light& light, const SurfaceId& surface) const {
    return light.emitter().isDirectSource() && !(surface && light.surface() == surface);
}

void LightSampler::drawnFrom(PathState& child, const dvec3& from, double pdf, const PathState& parent) const {
    child.kind = PathState::Kind::Sampled;
    child.skyNormal = dvec3(0);
    child.from = from;
    child.fromWeight = parent.weight;
    child.fromSubdivision = subdivision(parent);
    child.sampledDensity = pdf;
}

double LightSampler::misWeight(const Light& light, const PathState& state, const Ray& ray, const SurfaceHit* hit) const {
    // Distance from where the sampled ray left: it may have crossed clear glass on the way.
    double dist = hit ? glm::length(hit->point - state.from) : std::numeric_limits<double>::infinity();
    dvec3 normal = hit ? hit->normal : dvec3(0);
    double lightDensity = light.pdf(state.from, ray.dir, dist, normal) *
                          light.sampleCount(state.from, state.fromSubdivision, state.fromWeight);
    return powerHeuristic(state.sampledDensity, lightDensity);
}

// Every source sample. Diffuse lobes take their source light from here alone, as in Radiance (a few
// stratified shadow rays beat thousands of diffuse rays that rarely find a small source); lobes that are
// also sampled by rays share it with them by the power heuristic.
// Whether a scattering more may count where `state` is: the flames' light scattered by their own smoke on its
// way is one (its paths, flame to smoke to here, are a bounce longer than the emission's).
bool LightSampler::bounceLeft(const PathState& state) const {
    return state.ambientLevel < settings_.ambientBounces || settings_.bounceTail();
}

Spectrum LightSampler::sampleLdSharingFlames(const Scatterer& at, const PathState& state, PathContext& ctx,
                                             double flameShare) const {
    return sourcesLd(at, SurfaceId{}, state, ctx, nullptr) +
           flames_.sample(at, SurfaceId{}, state, subdivision(state), bounceLeft(state), ctx, flameShare);
}

Spectrum LightSampler::sampleLd(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                                PathContext& ctx, const SourceShares* shares) const {
    return sourcesLd(at, surface, state, ctx, shares) +
           flames_.sample(at, surface, state, subdivision(state), bounceLeft(state), ctx);
}

Spectrum LightSampler::besidesRecords(const Scatterer& at, const PathState& state, PathContext& ctx) const {
    Spectrum value = flames_.sample(at, SurfaceId{}, state, subdivision(state), bounceLeft(state), ctx);
    if (mirrorImagesOn()) value += directViaMirrors(at, SurfaceId{}, state, ctx);
    return value;
}

Spectrum LightSampler::sourcesLd(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                                 PathContext& ctx, const SourceShares* shares) const {
    const std::vector<Light>& lights = scene_.lights();
    if (state.ambientLevel > 0 && !at.sampledByRays())
        if (auto one = oneSourceOf(at, surface, state, ctx, shares)) return *one;
    // Diffuse light of uniform sources: their unoccluded value in closed form (see directFrom), and how
    // bright it is in all, for -dt.
    std::vector<double>& closedForm = ctx.scratch.perSource;
    closedForm.assign(lights.size(), -1.0);
    double total = 0;
    if (exactDirect(state) && at.lambertian())
        for (size_t i = 0; i < lights.size(); ++i) {
            if (!samplesSource(lights[i], surface)) continue;
            closedForm[i] = lights[i].unoccludedIrradiance(at.point(), at.surface()->normal);
            total += std::max(0.0, closedForm[i]) * brightness(lights[i].emitter().radiance);
        }
    Spectrum sum(0.f);
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!samplesSource(lights[i], surface)) continue;
        double share = closedForm[i] > 0 && total > 0 ? closedForm[i] * brightness(lights[i].emitter().radiance) / total : 1.0;
        sum += keptFrom(lights[i], closedForm[i], share, 1.0, at, surface, state, ctx, shares);
    }
    if (mirrorImagesOn()) sum += directViaMirrors(at, surface, state, ctx);
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
std::optional<Spectrum> LightSampler::oneSourceOf(const Scatterer& at, const SurfaceId& surface,
                                                  const PathState& state, PathContext& ctx,
                                                  const SourceShares* shares) const {
    const std::vector<Light>& lights = scene_.lights();
    std::vector<double>& guess = ctx.scratch.perSource;
    guess.assign(lights.size(), 0.0);
    double total = 0;
    int candidates = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        if (!samplesSource(light, surface)) continue;
        guess[i] = light.roughSolidAngle(at.point()) * std::max(1e-30f, brightness(light.emitter().radiance));
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
    Spectrum value = keptFrom(lights[chosen], -1, 1.0, 1 / probability(chosen), at, surface, state, ctx, shares);
    if (mirrorImagesOn()) value += directViaMirrors(at, surface, state, ctx);
    return value;
}

// One source's light taken with `weight` (1, or 1/p where it stands for all the sources), times the share it
// keeps at `at` (SourceShares): asked first where contributions are told (its samples carry it), else only where
// the source shines.
Spectrum LightSampler::keptFrom(const Light& light, double closedForm, double share, double weight, const Scatterer& at,
                                const SurfaceId& surface, const PathState& state, PathContext& ctx,
                                const SourceShares* shares) const {
    auto kept = [&] { return shares ? shares->rayShare(light, at, surface, state, ctx) : 1.0; };
    double told = state.throughput ? kept() : 1.0;
    Spectrum value = directFrom(light, closedForm, share, told * weight, at, surface, state, ctx) * float(weight);
    if (shares && !value.isBlack()) value *= float(state.throughput ? told : kept());
    return value;
}

// One source's light. With `closedForm` ≥ 0, the diffuse part is that unoccluded value less what the
// shadow rays find blocked (a control variate): exact where nothing is in the way, noisy only in shadows.
// Each sample is told to the contributions times `scale`, the factor the caller then applies to the value.
Spectrum LightSampler::directFrom(const Light& light, double closedForm, double share, double scale,
                                  const Scatterer& at, const SurfaceId& surface, const PathState& state,
                                  PathContext& ctx) const {
    const Emitter& e = light.emitter();
    const dvec3& point = at.point();
    Spectrum sum(0.f);
    Spectrum blocked(0.f);  // estimate of the irradiance the closed form counts but obstacles stop
    bool anyThrough = false;  // some controlled shadow ray got through
    // Multiple importance weights take the count rays sampled by lobes assume (misWeight): any weights that
    // sum to one keep the estimate unbiased.
    int nominal = std::max(light.sampleCount(point, subdivision(state), state.weight), state.sensor ? sensorRays_ : 1);
    int count = thresholdedCount(nominal, share);
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    if (e.radiance.isBlack()) return sum;
    LightView view = light.view(point);
    Spectrum scratch;  // the radiance of patterned and focused sources (see sourceRadiance)
    PatternEvaluator& patterns = ctx.scratch.patterns;
    bool record = ctx.outputs && ctx.outputs->wantsShadowRays();
    bool told = ctx.contributions && state.throughput;
    int modifier = told ? scene_.lightModifier(light) : -1;
    for (int k = 0; k < count; ++k) {
        double u, v;
        sobol2D(k, scramble, u, v);
        auto s = light.sample(view, u, v);
        if (!s) continue;
        if (e.kind == Emitter::Kind::Glow && s->distance > e.glowRadius) continue;
        double cosL = at.cosine(s->dir);
        bool controlled = closedForm >= 0 && cosL > 0;
        Spectrum f = at.response(s->dir, s->pdf * nominal, !controlled);
        if (f.isBlack() && !controlled) continue;
        Ray shadow{point, s->dir, std::numeric_limits<double>::infinity(), surface};
        float weight = float(1 / (s->pdf * count));
        Spectrum t;
        Occlusion seen = passage(shadow, light, s->distance, state, ctx, t);
        if (seen == Occlusion::Unsure) {
            const Spectrum& le = sourceRadiance(light, *s, point, scratch, patterns);
            if (record) recordShadowRay(ctx, point, *s, light, le * t);
            sum.addProduct(f * t, le, weight);
            if (told) contribute(ctx, state, modifier, point, s->dir, s->distance, s->normal, f * t * float(weight * scale), le);
            if (controlled) {
                blocked += (Spectrum(1.f) - t) * float(cosL * weight);
                anyThrough = anyThrough || !t.isBlack();
            }
            continue;
        }
        // Transmission 1 or 0 in every channel: the same sums as above without a spectrum per ray, and the
        // source's pattern evaluated only where it is seen.
        bool clear = seen == Occlusion::Clear;
        if (record) recordShadowRay(ctx, point, *s, light, sourceRadiance(light, *s, point, scratch, patterns) * float(clear));
        if (clear && !f.isBlack()) {
            const Spectrum& le = sourceRadiance(light, *s, point, scratch, patterns);
            sum.addProduct(f, le, weight);
            if (told) contribute(ctx, state, modifier, point, s->dir, s->distance, s->normal, f * float(weight * scale), le);
        }
        if (controlled && !clear) blocked += float(cosL * weight);
        anyThrough = anyThrough || (controlled && clear);
    }
    if (closedForm >= 0 && anyThrough) {
        // Every ray blocked means shadow: 0, not the closed form less a noisy estimate of itself (for the
        // sun, that noise alone would be a visible glow in every shadow). In penumbrae the estimate of
        // what is blocked can still exceed the whole: never below 0.
        Spectrum unblocked = Spectrum(float(closedForm)) - blocked;
        for (int c = 0; c < unblocked.size(); ++c) unblocked[c] = std::max(0.f, unblocked[c]);
        sum += *at.lambertian() * e.radiance * unblocked * float(1 / kPi);
        if (told) {  // told as one contribution from the source's centre
            dvec3 toward = light.isDistant() ? light.direction() : light.center() - point;
            double distance = light.isDistant() ? std::numeric_limits<double>::infinity() : glm::length(toward);
            toward = glm::normalize(toward);
            contribute(ctx, state, modifier, point, toward, distance, -toward,
                       *at.lambertian() * unblocked * float(scale / kPi), e.radiance);
        }
    }
    return sum;
}

Occlusion LightSampler::passage(const Ray& shadow, const Light& light, double distance, const PathState& state,
                                PathContext& ctx, Spectrum& t) const {
    Occlusion seen = scene_.geometry().occlusion(shadow, light.surface(), distance, scene_);
    if (seen == Occlusion::Unsure) t = shadowRays_.toSource(shadow, light, state, ctx);
    else if (seen == Occlusion::Clear && media_.attenuates(shadow, distance, state, ctx.smoke))
        t = media_.clearTransmittance(shadow, distance, state, ctx.smoke), seen = Occlusion::Unsure;
    return seen;
}

void LightSampler::arriving(const Light& light, const Receiver& at, const SurfaceId& leaving, int count,
                            const PathState& state, PathContext& ctx, SourceSamples& out) const {
    const Emitter& e = light.emitter();
    if (!samplesSource(light, leaving) || e.radiance.isBlack()) return;
    uint64_t scramble = (uint64_t(ctx.rng.next()) << 32) | ctx.rng.next();
    LightView view = light.view(at.point);
    Spectrum scratch;
    for (int k = 0; k < count; ++k) {
        double u, v;
        sobol2D(k, scramble, u, v);
        auto s = light.sample(view, u, v);
        if (!s || (e.kind == Emitter::Kind::Glow && s->distance > e.glowRadius)) continue;
        if (at.normal && !(glm::dot(*at.normal, s->dir) > 0)) continue;
        Spectrum t;
        Occlusion seen = passage(Ray{at.point, s->dir, std::numeric_limits<double>::infinity(), leaving}, light,
                                 s->distance, state, ctx, t);
        if (seen == Occlusion::Blocked) continue;
        Spectrum flux = sourceRadiance(light, *s, at.point, scratch, ctx.scratch.patterns) * float(1 / (s->pdf * count));
        if (seen == Occlusion::Unsure) flux *= t;
        if (!flux.isBlack()) out.push_back({s->dir, s->distance, flux});
    }
}

// The radiance a source sample sends toward `from`: the emitter's own, or, with Radiance's spotlight focus (a
// spotlight acts as if it were its focal distance farther behind its surface) and the source's pattern,
// `scratch` made so, without a spectrum per sample.
const Spectrum& LightSampler::sourceRadiance(const Light& light, const LightSample& s, const dvec3& from,
                                             Spectrum& scratch, PatternEvaluator& patterns) const {
    const Emitter& e = light.emitter();
    bool finite = std::isfinite(s.distance);
    bool focused = e.kind == Emitter::Kind::Spotlight && finite;
    if (!focused && !light.patterned()) return e.radiance;
    scratch = e.radiance;
    if (focused)
        scratch *= float(s.distance * s.distance / ((s.distance + e.spotFocus) * (s.distance + e.spotFocus)));
    if (light.patterned())
        scratch *= shading_.sourcePattern(light, finite ? from + s.distance * s.dir : from, s.normal, s.dir,
                                          finite ? s.distance : kDistantSourceDistance, patterns);
    return scratch;
}

void LightSampler::recordShadowRay(PathContext& ctx, const dvec3& from, const LightSample& s, const Light& light,
                                   const Spectrum& value) const {
    ctx.outputs->shadowRay(from, s, light.object(), scene_.lightModifier(light), value);
}

// Sources seen in flat mirrors (Radiance's virtual sources, one relay): each source is sampled as seen
// from the shading point's mirror image, and the shadow ray goes to the mirror and on to the source.
// Sampled rays that take the same route count nothing (see Integrator::emitterHit), so each path counts once.
Spectrum LightSampler::directViaMirrors(const Scatterer& at, const SurfaceId& surface, const PathState& state,
                                        PathContext& ctx) const {
    const dvec3& point = at.point();
    Spectrum sum(0.f);
    Spectrum scratch;
    for (const PlanarMirror& mirror : scene_.planarMirrors()) {
        double height = glm::dot(mirror.normal, point) - mirror.offset;
        if (mirror.surface == surface || height <= 0) continue;  // mirrors reflect from their front only
        dvec3 image = point - 2 * height * mirror.normal;
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
                Spectrum f = at.response(d, 0);
                if (f.isBlack()) continue;
                PathState crossing = state;
                SurfaceHit onMirror;
                Spectrum t = shadowRays_.toSurface(Ray{point, d, std::numeric_limits<double>::infinity(), surface},
                                                   mirror.surface, false, e.kind, crossing, ctx, &onMirror);
                if (t.isBlack()) continue;
                Ray onward{onMirror.point, s->dir, std::numeric_limits<double>::infinity(), mirror.surface};
                // The source's sample lies along the onward ray only if the way to the mirror went straight.
                Occlusion seen = scene_.shadowsBend() ? Occlusion::Unsure
                                                      : scene_.geometry().occlusion(onward, light.surface(),
                                                                                    s->distance - toMirror, scene_);
                if (seen == Occlusion::Blocked) continue;
                if (seen == Occlusion::Unsure) t *= shadowRays_.toSource(onward, light, crossing, ctx);
                else if (media_.present()) t *= media_.clearTransmittance(onward, s->distance - toMirror, crossing, ctx.smoke);
                if (t.isBlack()) continue;
                const Spectrum& le = sourceRadiance(light, *s, image, scratch, ctx.scratch.patterns);
                sum += f * le * mirror.reflectance * t * float(1 / (s->pdf * count));
                if (ctx.contributions && state.throughput)
                    contribute(ctx, state, scene_.lightModifier(light), point, d, s->distance, s->normal,
                               f * mirror.reflectance * t * float(1 / (s->pdf * count)), le);
            }
        }
    }
    return sum;
}

}  // namespace brume
