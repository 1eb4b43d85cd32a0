// Transforming scene text as Radiance's xform does: comments copied, "!command" lines run (their output
// transformed in place) or passed on, every object transformed by the rules of its type.
#pragma once
#include <istream>
#include <ostream>
#include <string>

#include "scene/transform_object.h"

namespace brume {

struct SceneTransform {
    ObjectTransform objects;
    // xform -e (the default) runs "!command" lines and transforms their output; xform -c writes them on,
    // followed by `commandPipe` (" | xform -e -t 1 0 0"), which transforms their output when the scene is read.
    bool expandCommands = true;
    std::string commandPipe;
};

// Writes the scene text read from `in` (called `name` in messages) to `out`, transformed, each object and
// command after an empty line, as Radiance's xform writes them. Throws Error at the first object that
// cannot be transformed or command that fails.
void transformSceneText(std::istream& in, const std::string& name, const SceneTransform& how, std::ostream& out);

}  // namespace brume
