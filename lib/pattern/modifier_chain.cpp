#include "pattern/modifier_chain.h"

#include <algorithm>
#include <set>

#include "pattern/pattern_types.h"
#include "pattern/spectral_pattern.h"
#include "util/error.h"

namespace brume {

bool isPatternType(const std::string& t) {
    static const std::set<std::string> kTypes{"brightfunc", "colorfunc", "brightdata", "colordata", "colorpict",
                                              "brighttext", "colortext", "texfunc",    "texdata"};
    return kTypes.count(t) > 0 || isSpectralPatternType(t);
}

bool isMixtureType(const std::string& t) { return t == "mixfunc" || t == "mixdata" || t == "mixpict" || t == "mixtext"; }

ModifierChain::ModifierChain(const Scene& scene, const std::function<void(PatternLibrary&)>& alsoCompile)
    : scene_(scene), library_(std::make_unique<PatternLibrary>()), nodes_(scene.objects.size()) {
    // Modifiers precede their users, so one pass in order sees every chain's tail first.
    for (int i = 0; i < int(scene.objects.size()); ++i) build(i);
    if (alsoCompile) alsoCompile(*library_);
    library_->finish();
}

ModifierChain::~ModifierChain() = default;

void ModifierChain::build(int i) {
    const SceneObject& o = scene_.objects[i];
    Node& n = nodes_[i];
    const Node* next = o.modifier >= 0 ? &nodes_[o.modifier] : nullptr;
    if (isMaterialType(o.type) || isEmitterType(o.type) || o.type == "antimatter" || o.type == "mist") {
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
        n.pattern = makePattern(scene_, i, *library_);
        n.varies = true;
        n.reachesMaterial = next && next->reachesMaterial;
        n.fixedMaterial = next ? next->fixedMaterial : -1;
        return;
    }
    if (isMixtureType(o.type)) {
        n.kind = Kind::Mixture;
        n.mixture = makeMixture(scene_, i, *library_);
        n.varies = true;
        bool materials = reachesMaterial(n.mixture->foreground) || reachesMaterial(n.mixture->background);
        if (materials && o.modifier >= 0)
            throw Error(o.where, "inappropriate modifier for " + o.type + " \"" + o.name +
                                     "\": a mixture of materials must have the void modifier");
        n.reachesMaterial = materials || (next && next->reachesMaterial);
    }
}

double ModifierChain::coefficient(const Node& n, const PatternHit& hit, PatternEvaluator& eval) const {
    double c = n.mixture->coefficient(hit, eval);
    return c >= 0 ? std::min(c, 1.0) : 0.0;  // NaN too
}

// Patterns and textures along a chain without materials; its mixtures blend (Radiance's raymixture: both
// sides start from the texturing so far).
void ModifierChain::applyPatterns(int m, const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const {
    for (; m >= 0; m = scene_.objects[m].modifier) {
        const Node& n = nodes_[m];
        if (n.kind == Kind::Pattern) n.pattern->apply(hit, eval, t);
        if (n.kind == Kind::Mixture) blend(n, hit, eval, t);
    }
}

void ModifierChain::blend(const Node& n, const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const {
    double c = coefficient(n, hit, eval);
    Texturing f = t, b = t;
    applyPatterns(n.mixture->foreground, hit, eval, f);
    applyPatterns(n.mixture->background, hit, eval, b);
    t.color = f.color * float(c) + b.color * float(1 - c);
    t.perturbation = c * f.perturbation + (1 - c) * b.perturbation;
}

void ModifierChain::walk(int m, const PatternHit& hit, PatternEvaluator& eval, Shader s, double share,
                         Branches& out) const {
    for (; m >= 0; m = scene_.objects[m].modifier) {
        const Node& n = nodes_[m];
        if (n.kind == Kind::Material) {
            if (n.varies) applyPatterns(scene_.objects[m].modifier, hit, eval, s.texturing);
            s.material = m;
            out.add(s, share);
            return;
        }
        if (n.kind == Kind::Pattern) n.pattern->apply(hit, eval, s.texturing);
        if (n.kind != Kind::Mixture) continue;
        const Mixture& mix = *n.mixture;
        if (!reachesMaterial(mix.foreground) && !reachesMaterial(mix.background)) {
            blend(n, hit, eval, s.texturing);
            continue;
        }
        // A mixture of materials: one side, chosen by its share, or both (the side without a material is
        // see-through there).
        double c = coefficient(n, hit, eval);
        auto side = [&](int branch, double w) {
            if (reachesMaterial(branch)) walk(branch, hit, eval, s, share * w, out);
            else out.add(Shader{-1, s.texturing}, share * w);
        };
        if (out.u) {
            bool fore = *out.u < c;
            *out.u = fore ? *out.u / c : (*out.u - c) / (1 - c);
            side(fore ? mix.foreground : mix.background, 1);
        } else {
            if (c > 0) side(mix.foreground, c);
            if (c < 1) side(mix.background, 1 - c);
        }
        return;
    }
    s.material = -1;
    out.add(s, share);
}

void ModifierChain::Branches::add(const Shader& s, double w) {
    if (count < kMaxBranches) {
        shader[count] = s;
        share[count++] = w;
    } else {  // deeper than any real scene nests mixtures: the last branch stands for the rest
        share[count - 1] += w;
    }
}

Shader ModifierChain::resolve(int modifier, const PatternHit& hit, PatternEvaluator& eval, double u) const {
    Branches b;
    b.u = &u;
    walk(modifier, hit, eval, Shader{}, 1, b);
    return b.shader[0];
}

int ModifierChain::resolveAll(int modifier, const PatternHit& hit, PatternEvaluator& eval, Branches& out) const {
    out.count = 0;
    out.u = nullptr;
    walk(modifier, hit, eval, Shader{}, 1, out);
    return out.count;
}

}  // namespace brume
