#include "pattern/function_object.h"

#include <algorithm>

#include "util/error.h"

namespace brume {

void badArguments(const SceneObject& o, const std::string& why) {
    throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\": " + why);
}

FunctionObject functionObject(const SceneObject& o, PatternLibrary& lib, size_t file, size_t first, size_t count) {
    if (o.strings.size() < std::max(file + 1, first + count)) badArguments(o, "too few string arguments");
    if (!o.integers.empty()) badArguments(o, "no integer arguments expected");
    FunctionObject f;
    f.scope = lib.load(o.strings[file], o.where);
    for (size_t i = first; i < first + count; ++i) f.exprs.push_back(lib.expression(o.strings[i], f.scope, o.where));
    size_t after = std::max(file + 1, first + count);
    f.frame = PatternFrame::fromArguments(o, std::span(o.strings).subspan(after));
    f.args = o.reals;
    return f;
}

}  // namespace brume
