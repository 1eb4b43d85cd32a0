// A pattern's own coordinate system, given by the transform at the end of its string arguments, and the
// ray values (Radiance's channels $1…$27) its function file reads in it (Radiance's rt/func.c).
#pragma once
#include <span>
#include <string>

#include "cal/channels.h"
#include "geometry/transform.h"
#include "pattern/pattern.h"
#include "scene/scene.h"

namespace brume {

struct PatternFrame {
    Transform toWorld;    // pattern → world, as the arguments say
    Transform toPattern;  // world → pattern

    // Reads the transform from `args` (everything from the first transform option on). Throws Error
    // (file:line) when the transform is malformed.
    static PatternFrame fromArguments(const SceneObject& o, std::span<const std::string> args);

    // The hit in pattern coordinates, as the function file sees it.
    void channels(const PatternHit& hit, cal::Channels& c) const;
    // A vector computed in pattern coordinates (a texture's normal perturbation, an anisotropic material's
    // u direction), in world coordinates.
    dvec3 toWorldVector(const dvec3& d, const PatternHit& hit) const;
    // A world direction as the function file sees directions (turned into its axes, unit length kept).
    dvec3 toPatternDirection(const dvec3& d, const PatternHit& hit) const;

private:
    // World → pattern coordinates at this hit (through the instance's frame, if any).
    Transform fromWorld(const PatternHit& hit) const;
};

}  // namespace brume
