// Radiance's text patterns and mixture (reference manual, "Colortext", "Brighttext", "Mixtext"; the
// argument layouts and the text's placement follow its rt/text.c): writing in a polygonal font on a plane,
// given inline or read from a text file, placed by its upper left corner and right and down vectors.
#pragma once
#include <memory>

#include "pattern/pattern.h"
#include "pattern/pattern_library.h"
#include "scene/scene.h"

namespace brume {

// brighttext and colortext: the material's colour multiplied by the foreground value inside glyphs, the
// background value elsewhere. Throws Error (file:line) on bad arguments, a font or text file that cannot
// be found or read, or right and down vectors that span no plane.
std::unique_ptr<Pattern> makeTextPattern(const SceneObject& o, PatternLibrary& library);

// mixtext: coefficient 1 (the foreground modifier) inside glyphs, 0 outside. The caller sets the two
// modifiers, named by the first two string arguments.
std::unique_ptr<Mixture> makeTextMixture(const SceneObject& o, PatternLibrary& library);

}  // namespace brume
