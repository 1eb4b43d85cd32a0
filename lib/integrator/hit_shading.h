// What shades a hit: the surface's material or emitter after its patterns, textures and mixtures, an illum's
// alternate material, antimatter that cuts surfaces away and mists whose boundaries a ray crosses; and the
// hit as the material sees it (its normal turned toward the ray and perturbed).
#pragma once
#include "integrator/path_state.h"
#include "material/material.h"
#include "pattern/pattern_evaluator.h"
#include "world/render_scene.h"

namespace brume {

struct Scratch;

// The hit as a material sees it: the normal, perturbed (by mesh normals and a texture's `texture`), turned
// toward the ray, and which side was hit.
Shading shadingAt(const Ray& ray, const SurfaceHit& hit, bool flat, const ObjectFrame* object,
                  const dvec3& texture = dvec3(0));
// The patterns' colour, and the texture's perturbation added to the hit's own (mesh normals), as Radiance's
// raytexture adds to the ray's before raynormal.
void applyTexturing(Shading& sh, const Texturing& t, const Ray& ray, const SurfaceHit& hit);

class HitShading {
public:
    explicit HitShading(const RenderScene& scene) : scene_(scene) {}

    // What shades the hit: the surface's material, or what its patterns and mixtures make of it here (then
    // `sh` takes their colour and perturbed normal; a mixture draws from `rng`). -1: nothing, the ray goes on.
    int shaderAt(const Ray& ray, const SurfaceHit& hit, Shading& sh, Random& rng, PatternEvaluator& patterns) const;
    // An illum's alternate material, as Radiance's m_light passes rays to it: shaded with that material's own
    // modifiers, never the illum's (its pattern is the distribution of the light the illum sends, not a colour
    // of the glass). `sh` is made anew for it. Null where the illum has none (void): the ray goes on.
    const Material* alternateMaterial(const Ray& ray, const SurfaceHit& hit, const Emitter& illum, Shading& sh,
                                      Random& rng, PatternEvaluator& patterns) const;
    // A primary ray's hit on a surface whose mixtures blend (Radiance's raymixture): every material with its share.
    int blend(const Ray& ray, const SurfaceHit& hit, PatternEvaluator& patterns, ModifierChain::Branches& out) const;
    // The hit as patterns see it: in an instance or mesh, in its frame, with the mesh's (u, v).
    PatternHit patternHit(const Ray& ray, const SurfaceHit& hit) const {
        return PatternHit{hit.point, ray.dir, hit.normal, hit.t, hit.uv.x, hit.uv.y, scene_.objectFrame(hit.surface)};
    }
    // The hit as a material sees it, for Material::scatter: materials with function files evaluate them on the
    // hit as Radiance does after its flipsurface, the normal turned toward the ray (`functionHit` holds it).
    Shading forMaterial(const Ray& ray, const SurfaceHit& hit, const Shading& sh, PatternHit& functionHit,
                        PatternEvaluator& patterns) const {
        functionHit = patternHit(ray, hit);
        if (sh.backside) functionHit.normal = -functionHit.normal;
        Shading at = sh;
        at.hit = &functionHit;
        at.evaluator = &patterns;
        return at;
    }
    // The colour of a source's patterns where a ray in direction `dir` meets it (e.g. a luminaire's intensity
    // distribution from ies2rad, or a sky's luminance distribution).
    Spectrum sourcePattern(const Light& light, const dvec3& point, const dvec3& normal, const dvec3& dir,
                           double distance, PatternEvaluator& patterns) const;

    // The state of a path starting at p: in the mists around p (see hit_shading.cpp).
    PathState startingAt(const dvec3& p, Scratch& scratch) const;
    // Whether the modifier is cut away by an antimatter volume the ray is in.
    bool clipped(int modifier, const PathState& state) const;
    // Antimatter and mist surfaces are not seen: crossing one (they face outward) enters or leaves its volume.
    bool crossesAntimatter(int material, bool backside, PathState& state) const;
    bool crossesMist(int material, bool backside, PathState& state) const;
    // Whether a hit by material `mat` (-1: none) lets the ray go on unseen: no material, cut away, or the
    // boundary of an antimatter or mist volume, which `state` then enters or leaves.
    bool passes(int mat, bool backside, PathState& state) const {
        return mat < 0 || (state.clips.count > 0 && clipped(mat, state)) || crossesAntimatter(mat, backside, state) ||
               crossesMist(mat, backside, state);
    }

private:
    const RenderScene& scene_;
};

}  // namespace brume
