// Moving one scene object as Radiance's xform does, by the rules of its type: points move, directions
// turn, sizes scale by |scale|, lengths of media scale inversely, and types whose functions (.cal) see the
// scene carry the transform in their string arguments, to apply it when they are evaluated.
#pragma once
#include <string>
#include <vector>

#include "geometry/transform.h"
#include "scene/object_text.h"

namespace brume {

struct ObjectTransform {
    Transform transform;
    // The transform as written on the command line ("-rz 90 -t 1 0 0"): appended to the string arguments
    // of instances, meshes and function types.
    std::vector<std::string> words;
    bool invert = false;   // -I: surfaces turned inside out
    std::string prefix;    // -n: surface identifiers become "prefix.identifier"
    std::string modifier;  // -m: the modifier of every surface
};

// Transforms `object` in place. Throws Error (at the object's file:line) for an unknown type or arguments
// that do not fit the type, as Radiance's xform checks them.
void transformObject(ObjectText& object, const ObjectTransform& how);

}  // namespace brume
