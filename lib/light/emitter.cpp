#include "light/emitter.h"
#include "spectrum/rgb_to_spectrum.h"

#include <numbers>

namespace brume {

Emitter makeEmitter(const Scene& scene, int index) {
    const SceneObject& o = scene.objects[index];
    Emitter e;
    size_t reals = 3, maxStrings = 0;
    if (o.type == "glow") e.kind = Emitter::Kind::Glow, reals = 4;
    else if (o.type == "spotlight") e.kind = Emitter::Kind::Spotlight, reals = 7;
    else if (o.type == "illum") e.kind = Emitter::Kind::Illum, maxStrings = 1;
    if (o.strings.size() > maxStrings || !o.integers.empty() || o.reals.size() != reals)
        throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\"");
    e.radiance = spectrumFromRgb(o.reals[0], o.reals[1], o.reals[2]);
    if (e.kind == Emitter::Kind::Glow) e.glowRadius = o.reals[3];
    if (e.kind == Emitter::Kind::Spotlight) {
        double angle = o.reals[3] * std::numbers::pi / 180;
        dvec3 aim(o.reals[4], o.reals[5], o.reals[6]);
        e.spotFocus = glm::length(aim);
        if (!(e.spotFocus > 0) || !(angle > 0))
            throw Error(o.where, "bad cone angle or direction for spotlight \"" + o.name + "\"");
        e.spotAxis = aim / e.spotFocus;
        e.spotCosHalf = std::cos(std::min(angle, 2 * std::numbers::pi) / 2);
    }
    if (e.kind == Emitter::Kind::Illum && !o.strings.empty() && o.strings[0] != "void") {
        e.alternate = scene.modifierBefore(index, o.strings[0]);
        if (e.alternate < 0)
            throw Error(o.where, "undefined alternate material \"" + o.strings[0] + "\" for illum \"" + o.name + "\"");
    }
    return e;
}

}  // namespace brume
