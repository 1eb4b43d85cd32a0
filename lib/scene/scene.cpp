#include "scene/scene.h"

#include <algorithm>
#include <set>

namespace brume {

namespace {

// Radiance's eqreal: equal within a relative 1e-6 (its FTINY), or absolute when b is 0.
bool nearlyEqual(double a, double b) {
    double d = b != 0 ? a / b - 1 : a;
    return -1e-6 <= d && d <= 1e-6;
}

// How many leading string arguments of `object` name modifiers (Radiance's eqobjects special cases).
size_t modifierStrings(const SceneObject& object) {
    size_t n = object.strings.size();
    if (object.type == "illum" || object.type == "mirror") return std::min<size_t>(n, 1);
    if (object.type == "mixfunc" || object.type == "mixdata" || object.type == "mixtext" || object.type == "mixpict")
        return n >= 2 ? 2 : 0;
    if (object.type == "antimatter") return n;
    return 0;
}

}  // namespace

bool isModifierType(std::string_view type) {
    // Radiance's T_S (surface) and T_V (volume) types, from its otypes.h, and Brume's smoke (a volume).
    static constexpr std::string_view kNotModifiers[] = {"polygon", "cone",  "sphere", "ring",
                                                         "cylinder", "cup",  "bubble", "tube",
                                                         "source",   "instance", "mesh", "smoke"};
    return std::find(std::begin(kNotModifiers), std::end(kNotModifiers), type) == std::end(kNotModifiers);
}

bool isMaterialType(const std::string& t) {
    static const std::set<std::string> kTypes{"plastic", "metal",  "trans",  "mirror",
                                              "glass",   "dielectric", "plastic2", "metal2", "trans2", "BSDF"};
    return kTypes.count(t) > 0 || isFunctionBrdfType(t);
}

bool isFunctionBrdfType(const std::string& t) {
    return t == "plasfunc" || t == "metfunc" || t == "transfunc" || t == "plasdata" || t == "metdata" ||
           t == "transdata";
}

bool isSurfaceType(const std::string& t) {
    return t == "sphere" || t == "bubble" || t == "polygon" || t == "cone" || t == "cup" || t == "cylinder" ||
           t == "tube" || t == "ring";
}

bool isEmitterType(const std::string& t) { return t == "light" || t == "spotlight" || t == "glow" || t == "illum"; }

int Scene::add(SceneObject object) {
    int index = static_cast<int>(objects.size());
    bool modifier = isModifierType(object.type);
    std::string name = modifier ? object.name : std::string();
    objects.push_back(std::move(object));
    if (modifier) {
        auto [it, added] = lastDefinition.try_emplace(name, index);
        if (!added && !sameDefinition(index, it->second)) it->second = index;
    }
    return index;
}

int Scene::findModifier(const std::string& name) const {
    auto it = lastDefinition.find(name);
    return it == lastDefinition.end() ? -1 : it->second;
}

// The indexed one if it is older, or else the latest one before the object.
int Scene::modifierBefore(int object, const std::string& name) const {
    if (int indexed = findModifier(name); indexed < object) return indexed;
    while (--object >= 0)
        if (objects[object].name == name && isModifierType(objects[object].type)) return object;
    return -1;
}

// Whether objects a and b define the same thing, down their modifier chains (Radiance's eqobjects).
bool Scene::sameDefinition(int a, int b) const {
    for (; a != b; a = objects[a].modifier, b = objects[b].modifier) {
        if (a < 0 || b < 0) return false;
        const SceneObject &x = objects[a], &y = objects[b];
        if (x.type != y.type || x.strings.size() != y.strings.size() || x.integers != y.integers ||
            x.reals.size() != y.reals.size())
            return false;
        for (size_t i = 0; i < x.reals.size(); ++i)
            if (!nearlyEqual(x.reals[i], y.reals[i])) return false;
        size_t references = modifierStrings(x);
        for (size_t i = 0; i < x.strings.size(); ++i) {
            bool same = i < references ? sameDefinition(modifierBefore(a, x.strings[i]), modifierBefore(b, y.strings[i]))
                                       : x.strings[i] == y.strings[i];
            if (!same) return false;
        }
    }
    return true;
}

}  // namespace brume
