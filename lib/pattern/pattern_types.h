// The pattern, texture and mixture types, built from their scene objects.
#pragma once
#include <memory>

#include "pattern/pattern.h"
#include "pattern/pattern_library.h"
#include "scene/scene.h"

namespace brume {

// Throw Error (file:line) on bad arguments or files that cannot be read.
std::unique_ptr<Pattern> makePattern(const Scene& scene, int object, PatternLibrary& library);
std::unique_ptr<Mixture> makeMixture(const Scene& scene, int object, PatternLibrary& library);

}  // namespace brume
