#include "integrator/hit_shading.h"

#include <cmath>

#include "integrator/scratch.h"

namespace brume {

using namespace integrator_detail;

Shading shadingAt(const Ray& ray, const SurfaceHit& hit, bool flat, const ObjectFrame* object, const dvec3& texture) {
    double along = glm::dot(hit.normal, ray.dir);
    bool backside = along > 0;
    Shading sh{hit.point, backside ? -hit.normal : hit.normal, ray.dir, std::abs(along), backside, flat, hit.t};
    sh.object = object;
    dvec3 perturbation = hit.perturbation + texture;
    if (perturbation == dvec3(0)) return sh;
    // Radiance's raynormal: the perturbed normal turns with the surface; where it would face away from the
    // ray, it is mirrored across the plane normal to the ray; its cosine is kept at least 0.001.
    dvec3 n = hit.normal + perturbation;
    double len = glm::length(n);
    if (!(len > 0) || !std::isfinite(len)) return sh;  // Radiance: "illegal normal perturbation", unperturbed
    n = (backside ? -n : n) / len;
    double cosine = -glm::dot(n, ray.dir);
    if (cosine <= 0) {
        n += 2 * cosine * ray.dir;
        cosine = -cosine;
    }
    sh.normal = n;
    sh.cosine = std::max(cosine, 0.001);
    sh.flat = false;
    return sh;
}

void applyTexturing(Shading& sh, const Texturing& t, const Ray& ray, const SurfaceHit& hit) {
    if (glm::dot(t.perturbation, t.perturbation) > 1e-12) sh = shadingAt(ray, hit, false, sh.object, t.perturbation);
    sh.pattern = t.color;
}

int HitShading::shaderAt(const Ray& ray, const SurfaceHit& hit, Shading& sh, Random& rng,
                         PatternEvaluator& patterns) const {
    if (!scene_.varies(hit.surface)) return scene_.materialObject(hit.surface);
    Shader s = scene_.modifiers().resolve(scene_.surfaceModifier(hit.surface), patternHit(ray, hit), patterns, rng.uniform());
    applyTexturing(sh, s.texturing, ray, hit);
    return s.material;
}

const Material* HitShading::alternateMaterial(const Ray& ray, const SurfaceHit& hit, const Emitter& illum, Shading& sh,
                                              Random& rng, PatternEvaluator& patterns) const {
    if (illum.alternate < 0) return nullptr;
    sh = shadingAt(ray, hit, sh.flat, sh.object);
    int material = illum.alternate;
    if (scene_.modifiers().varies(illum.alternate)) {
        Shader s = scene_.modifiers().resolve(illum.alternate, patternHit(ray, hit), patterns, rng.uniform());
        applyTexturing(sh, s.texturing, ray, hit);
        material = s.material;
    }
    return material >= 0 ? scene_.material(material) : nullptr;
}

int HitShading::blend(const Ray& ray, const SurfaceHit& hit, PatternEvaluator& patterns,
                      ModifierChain::Branches& out) const {
    return scene_.modifiers().resolveAll(scene_.surfaceModifier(hit.surface), patternHit(ray, hit), patterns, out);
}

Spectrum HitShading::sourcePattern(const Light& light, const dvec3& point, const dvec3& normal, const dvec3& dir,
                                   double distance, PatternEvaluator& patterns) const {
    PatternHit hit{point, dir, normal, distance};
    if (!light.isDistant()) hit.object = scene_.objectFrame(light.surface());
    return scene_.modifiers().resolve(scene_.lightModifier(light), hit, patterns, 0.5).texturing.color;
}

// Radiance knows a ray is in a mist only once it crosses the boundary; here a probe ray's first crossing of
// each mist's boundary tells, by the side it meets, whether p is inside. The last point asked about is
// remembered in the thread's scratch (a picture's eye).
PathState HitShading::startingAt(const dvec3& p, Scratch& scratch) const {
    PathState state;
    if (!scene_.hasMists()) return state;
    if (scratch.lastStart == p) {
        state.mists = scratch.mistsAtLastStart;
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
    scratch.lastStart = p, scratch.mistsAtLastStart = state.mists;
    return state;
}

bool HitShading::clipped(int modifier, const PathState& state) const {
    for (int i = 0; i < state.clips.count; ++i) {
        const std::vector<int>& cut = *scene_.clippedModifiers(state.clips.objects[i]);
        if (std::find(cut.begin(), cut.end(), modifier) != cut.end()) return true;
    }
    return false;
}

bool HitShading::crossesAntimatter(int mat, bool backside, PathState& state) const {
    if (!scene_.clippedModifiers(mat)) return false;
    if (backside) state.clips.leave(mat);
    else state.clips.enter(mat);
    return true;
}

bool HitShading::crossesMist(int mat, bool backside, PathState& state) const {
    if (!scene_.mist(mat)) return false;
    if (backside) state.mists.leave(mat);
    else state.mists.enter(mat);
    return true;
}

}  // namespace brume
