// Patterns, textures and mixtures: the modifiers between a surface and its material that vary it over the
// surface (Radiance reference manual, "Textures", "Patterns", "Mixtures"). Patterns multiply the material's
// colour, textures perturb its normal, mixtures choose between two modifiers.
#pragma once
#include <memory>
#include <vector>

#include "geometry/transform.h"
#include "spectrum/spectrum.h"

namespace brume {

// The hit as Radiance's function files see it, in world coordinates (each pattern maps it into its own).
struct PatternHit {
    dvec3 point;
    dvec3 dir;             // of the ray (unit)
    dvec3 normal;          // of the surface as it is oriented, not turned toward the ray
    double distance = 0;   // T and Ts: from the ray's origin
    double u = 0, v = 0;   // Lu, Lv: local coordinates on meshes
    const ObjectFrame* object = nullptr;  // for surfaces in instances and meshes
};

// What the modifiers did to the hit so far (Radiance's pcol and pert).
struct Texturing {
    Spectrum color = Spectrum(1.f);  // multiplies the material's colour, or an emitter's radiance
    dvec3 perturbation{0};           // added to the surface normal, in world coordinates
};

class PatternEvaluator;  // per-thread evaluation state (function-file variables), see pattern_evaluator.h

class Pattern {
public:
    virtual ~Pattern() = default;
    virtual void apply(const PatternHit& hit, PatternEvaluator& eval, Texturing& t) const = 0;
};

class Mixture {
public:
    virtual ~Mixture() = default;
    // The foreground's share, clamped to 0…1 by the caller.
    virtual double coefficient(const PatternHit& hit, PatternEvaluator& eval) const = 0;
    int foreground = -1, background = -1;  // modifier objects, -1 for void
};

}  // namespace brume
