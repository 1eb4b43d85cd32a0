// What every modifier driven by a function file has (patterns, textures, mixtures, and the materials with
// function files): its coordinate system, real arguments and compiled string arguments, evaluated in its
// function file's context (Radiance's getfunc and setfunc, rt/func.c).
#pragma once
#include <string>
#include <vector>

#include "cal/evaluator.h"
#include "pattern/pattern_evaluator.h"
#include "pattern/pattern_frame.h"
#include "pattern/pattern_library.h"
#include "scene/scene.h"

namespace brume {

struct FunctionObject {
    PatternFrame frame;
    std::vector<double> args;
    std::vector<cal::ExprId> exprs;
    cal::Scope scope;

    // Sets the evaluator up for this object at this hit.
    cal::Evaluator& begin(const PatternHit& hit, PatternEvaluator& e) const {
        frame.channels(hit, e.channels);
        e.eval.begin(e.channels, args);
        return e.eval;
    }
};

// Radiance's getfunc: strings[file] names the function file; strings[first … first+count) are expressions;
// the transform starts at the first transform option after them. Throws Error (file:line) on too few
// strings, integer arguments, undefined names or a bad transform.
FunctionObject functionObject(const SceneObject& o, PatternLibrary& lib, size_t file, size_t first, size_t count);

[[noreturn]] void badArguments(const SceneObject& o, const std::string& why);

}  // namespace brume
