// The modifiers between a surface and what shades it, walked as Radiance's rayshade and raytexture do:
// from the surface's modifier through patterns and textures to a material (or emitter), then through the
// material's own modifiers; a mixture picks one of two modifiers, or blends two chains of patterns.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "pattern/pattern.h"
#include "pattern/pattern_library.h"
#include "scene/scene.h"

namespace brume {

// What shades a hit once its modifiers are applied.
struct Shader {
    int material = -1;  // a material or emitter object; -1: nothing, the ray goes on through
    Texturing texturing;
};

class ModifierChain {
public:
    // Builds the pattern, texture and mixture objects of the scene (function files, data files and pictures
    // loaded once). Throws Error (file:line) for bad arguments, unknown modifiers, a mixture of materials with
    // a modifier of its own, or a material among a material's modifiers. `alsoCompile`, if given, adds what
    // else shares the patterns' program (the function files of materials) before it is finished.
    explicit ModifierChain(const Scene& scene, const std::function<void(PatternLibrary&)>& alsoCompile = nullptr);
    ~ModifierChain();

    // Whether the chain from `modifier` varies with the hit (a pattern, texture or mixture is on it).
    bool varies(int modifier) const { return modifier >= 0 && nodes_[modifier].varies; }
    // The material the chain from `modifier` ends in, patterns and textures skipped; -1 for void, or when a
    // mixture decides at each hit.
    int fixedMaterial(int modifier) const { return modifier >= 0 ? nodes_[modifier].fixedMaterial : -1; }

    // Walks the chain from `modifier` at this hit. A mixture of materials takes its foreground with
    // probability equal to its coefficient, drawn from u (uniform in [0, 1)).
    Shader resolve(int modifier, const PatternHit& hit, PatternEvaluator& eval, double u) const;

    // Every material the chain can end in here, with its share: mixtures of materials take both sides, as
    // Radiance's raymixture does. For rays whose value is the answer itself (primary rays), not noise.
    static constexpr int kMaxBranches = 8;
    struct Branches {
        Shader shader[kMaxBranches];
        double share[kMaxBranches];
        int count = 0;
        double* u = nullptr;  // set: choose one side of each mixture with it instead

        void add(const Shader& s, double w);
    };
    int resolveAll(int modifier, const PatternHit& hit, PatternEvaluator& eval, Branches& out) const;

    const PatternLibrary& library() const { return *library_; }

private:
    enum class Kind { Material, Pattern, Mixture, Other };
    struct Node {
        Kind kind = Kind::Other;
        bool varies = false;
        bool reachesMaterial = false;
        int fixedMaterial = -1;
        std::unique_ptr<Pattern> pattern;
        std::unique_ptr<Mixture> mixture;
    };

    void build(int object);
    bool reachesMaterial(int m) const { return m >= 0 && nodes_[m].reachesMaterial; }
    double coefficient(const Node& n, const PatternHit& hit, PatternEvaluator& eval) const;
    void walk(int modifier, const PatternHit& hit, PatternEvaluator& eval, Shader s, double share, Branches& out) const;
    void applyPatterns(int modifier, const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const;
    void blend(const Node& mixture, const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const;

    const Scene& scene_;
    std::unique_ptr<PatternLibrary> library_;
    std::vector<Node> nodes_;
};

// Whether objects of this type are patterns or textures (they modify a material) or mixtures.
bool isPatternType(const std::string& type);
bool isMixtureType(const std::string& type);

}  // namespace brume
