#include "pattern/modifier_chain.h"

#include <algorithm>
#include <set>

#include "light/emitter.h"
#include "material/material.h"
#include "pattern/pattern_types.h"
#include "util/error.h"

namespace brume {

bool isPatternType(const std::string& t) {
    static const std::set<std::string> kTypes{"brightfunc", "colorfunc", "brightdata", "colordata", "colorpict",
                                              "brighttext", "colortext", "texfunc",    "texdata"};
    return kTypes.count(t) > 0;
}

bool isMixtureType(const std::string& t) { return t == "mixfunc" || t == "mixdata" || t == "mixpict" || t == "mixtext"; }

ModifierChain::ModifierChain(const Scene& scene) : scene_(scene), nodes_(scene.objects.size()) {
    // Modifiers precede their users, so one pass in order sees every chain's tail first.
    for (int i = 0; i < int(scene.objects.size()); ++i) build(i);
}

ModifierChain::~ModifierChain() = default;

void ModifierChain::build(int i) {
    const SceneObject& o = scene_.objects[i];
    Node& n = nodes_[i];
    const Node* next = o.modifier >= 0 ? &nodes_[o.modifier] : nullptr;
    if (isMaterialType(o.type) || isEmitterType(o.type) || o.type == "antimatter") {
        if (next && next->reachesMaterial)
            throw Error(o.where, "conflicting material among the modifiers of " + o.type + " \"" + o.name + "\"");
        n.kind = Kind::Material;
        n.reachesMaterial = true;
        n.fixedMaterial = i;
        n.varies = next && next->varies;
        return;
    }
    if (isPatternType(o.type)) {
        n.kind = Kind::Pattern;
        n.pattern = makePattern(scene_, i);
        n.varies = true;
        n.reachesMaterial = next && next->reachesMaterial;
        n.fixedMaterial = next ? next->fixedMaterial : -1;
        return;
    }
    if (isMixtureType(o.type)) {
        n.kind = Kind::Mixture;
        n.mixture = makeMixture(scene_, i);
        n.varies = true;
        bool materials = reachesMaterial(n.mixture->foreground) || reachesMaterial(n.mixture->background);
        if (materials && o.modifier >= 0)
            throw Error(o.where, "inappropriate modifier for " + o.type + " \"" + o.name +
                                     "\": a mixture of materials must have the void modifier");
        n.reachesMaterial = materials || (next && next->reachesMaterial);
    }
}

void ModifierChain::applyPatterns(int m, const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const {
    double u = 0;  // never used: no materials here
    Shader s{-1, t};
    walk(m, hit, eval, u, s);
    t = s.texturing;
}

// Radiance's raymixture: each branch starts from the texturing so far; pattern-only branches are blended.
void ModifierChain::walk(int m, const PatternHit& hit, PatternEvaluator& eval, double& u, Shader& s) const {
    while (m >= 0) {
        const Node& n = nodes_[m];
        const SceneObject& o = scene_.objects[m];
        switch (n.kind) {
        case Kind::Material:
            if (n.varies) applyPatterns(o.modifier, hit, eval, s.texturing);
            s.material = m;
            return;
        case Kind::Pattern:
            n.pattern->apply(hit, eval, s.texturing);
            break;
        case Kind::Mixture: {
            const Mixture& mix = *n.mixture;
            double c = std::clamp(mix.coefficient(hit, eval), 0.0, 1.0);
            if (!(c >= 0)) c = 0;  // NaN
            if (!reachesMaterial(mix.foreground) && !reachesMaterial(mix.background)) {
                Shader f = s, b = s;
                walk(mix.foreground, hit, eval, u, f);
                walk(mix.background, hit, eval, u, b);
                s.texturing.color = f.texturing.color * float(c) + b.texturing.color * float(1 - c);
                s.texturing.perturbation = c * f.texturing.perturbation + (1 - c) * b.texturing.perturbation;
                break;
            }
            bool fore = u < c;
            u = fore ? u / c : (u - c) / (1 - c);
            int branch = fore ? mix.foreground : mix.background;
            if (!reachesMaterial(branch)) {  // the other side of a material: see-through
                s.material = -1;
                return;
            }
            m = branch;
            continue;
        }
        case Kind::Other:
            throw Error(o.where, o.type + " \"" + o.name + "\" cannot modify a surface");
        }
        m = o.modifier;
    }
    s.material = -1;
}

Shader ModifierChain::resolve(int modifier, const PatternHit& hit, PatternEvaluator& eval, double u) const {
    Shader s;
    walk(modifier, hit, eval, u, s);
    return s;
}

}  // namespace brume
