#include "pattern/pattern_types.h"

#include "util/error.h"

namespace brume {

std::unique_ptr<Pattern> makePattern(const Scene& scene, int object) {
    const SceneObject& o = scene.objects[object];
    throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
}

std::unique_ptr<Mixture> makeMixture(const Scene& scene, int object) {
    const SceneObject& o = scene.objects[object];
    throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
}

}  // namespace brume
