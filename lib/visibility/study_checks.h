// What is likely wrong with a visibility study's inputs, said before it runs: a sign that faces away from every
// eye (a polygon's vertex order gives its front), a sign or eyes inside solids (each of six rays along the axes
// from the point leaves a surface by its back), eyes outside the domain of the smoke's simulation.
#pragma once
#include <string>
#include <vector>

#include "visibility/study.h"
#include "world/scene_geometry.h"

namespace brume {

std::vector<std::string> studyWarnings(const VisibilityStudy& study, const SceneGeometry& geometry,
                                       const std::vector<SmokeDescription>& smoke);

// Whether p lies inside a closed solid of `geometry`: the six rays along the axes from it each meet a surface,
// and each from behind.
bool insideSolid(const SceneGeometry& geometry, const dvec3& p);

}  // namespace brume
