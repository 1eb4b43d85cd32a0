// Scene objects that are surfaces, turned into exact shapes.
#pragma once
#include <optional>

#include "geometry/surface.h"
#include "scene/scene.h"

namespace brume {

// The surface of scene object `index` (a sphere, bubble, polygon, cone, cup, cylinder, tube or ring). Throws
// Error (file:line) on malformed arguments; returns nullopt with a warning for a degenerate surface (e.g. a
// polygon of zero area), which Radiance also drops.
std::optional<Surface> makeSurface(const Scene& scene, int index);

}  // namespace brume
