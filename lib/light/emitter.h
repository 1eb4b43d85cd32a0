// Radiance's light-emitting materials: light, spotlight, glow and illum (reference manual §"Light
// Sources"). Emitters radiate from the front of their surface only, without a cosine falloff.
#pragma once
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/ray.h"
#include "scene/scene.h"
#include "spectrum/spectrum.h"

namespace brume {

struct Emitter {
    enum class Kind { Light, Spotlight, Glow, Illum };
    Kind kind = Kind::Light;
    Spectrum radiance;
    double glowRadius = 0;    // glow: a source only for points within this distance (≤ 0: never)
    double spotCosHalf = -1;  // spotlight: cosine of half the cone angle
    dvec3 spotAxis{0, 0, 1};  // spotlight: unit aim direction
    double spotFocus = 0;     // spotlight: distance of the focus behind the source (aim vector length)
    int alternate = -1;       // illum: scene object of the alternate material, -1 when invisible

    // Radiance emitted in direction `out` (unit, away from the surface's front); spotlights cut off hard.
    Spectrum emitted(const dvec3& out) const { return emitsToward(out) ? radiance : Spectrum(0.f); }
    bool emitsToward(const dvec3& out) const { return kind != Kind::Spotlight || !(glm::dot(out, spotAxis) < spotCosHalf); }
    // Whether next-event estimation samples it (glow only within its radius; see Radiance's glow).
    bool isDirectSource() const { return kind != Kind::Glow || glowRadius > 0; }
};

// The emitter described by scene object `index` (a light, spotlight, glow or illum). Throws Error on bad
// arguments. An illum's alternate material is the latest modifier so named before it (Radiance's lastmod).
Emitter makeEmitter(const Scene& scene, int index);

}  // namespace brume
