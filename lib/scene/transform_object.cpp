#include "scene/transform_object.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <unordered_map>

namespace brume {

namespace {

// What xform does to the arguments of each type Radiance knows (its otypes.h).
enum class Rule {
    Keep, AppendTransform, Source, Sphere, Polygon, Cone, Cylinder, Ring, Glow, Spotlight, Dielectric,
    Interface, Mist, Text, Smoke
};

std::optional<Rule> ruleOf(std::string_view type) {
    using enum Rule;
    static const auto rules = [] {
        std::unordered_map<std::string_view, Rule> r = {
            {"source", Source}, {"sphere", Sphere}, {"bubble", Sphere}, {"polygon", Polygon}, {"cone", Cone},
            {"cup", Cone}, {"cylinder", Cylinder}, {"tube", Cylinder}, {"ring", Ring}, {"glow", Glow},
            {"spotlight", Spotlight}, {"dielectric", Dielectric}, {"interface", Interface}, {"mist", Mist},
            {"smoke", Smoke}, {"brighttext", Text}, {"colortext", Text}, {"mixtext", Text}};
        // Octrees and meshes, and every type with functions: they take the transform with them.
        for (std::string_view t : {"instance", "mesh", "texfunc", "texdata", "plastic2", "metal2", "trans2",
                                   "plasfunc", "metfunc", "transfunc", "BRTDfunc", "BSDF", "aBSDF", "WGMDfunc",
                                   "plasdata", "metdata", "transdata", "ashik2", "prism1", "prism2", "brightfunc",
                                   "colorfunc", "brightdata", "colordata", "colorpict", "mixfunc", "mixdata",
                                   "mixpict", "specfunc", "specdata", "specpict"})
            r[t] = AppendTransform;
        // Nothing in their arguments depends on position, orientation or size.
        for (std::string_view t : {"alias", "plastic", "metal", "glass", "trans", "light", "illum", "mirror",
                                   "antimatter", "spectrum", "specfile"})
            r[t] = Keep;
        return r;
    }();
    auto it = rules.find(type);
    return it == rules.end() ? std::nullopt : std::optional(it->second);
}

// What is wrong with the arguments for the rule, as Radiance's xform checks them; empty if nothing.
std::string misfit(const SceneObject& o, Rule rule) {
    size_t n = o.reals.size();
    auto exactly = [&](size_t count) {
        return o.strings.empty() && n == count ? "" : "expected no strings and " + std::to_string(count) + " reals";
    };
    switch (rule) {
    case Rule::Source: case Rule::Sphere: case Rule::Glow: return exactly(4);
    case Rule::Cylinder: case Rule::Spotlight: return exactly(7);
    case Rule::Cone: case Rule::Ring: case Rule::Interface: return exactly(8);
    case Rule::Dielectric: return exactly(5);
    case Rule::Polygon: return o.strings.empty() && n % 3 == 0 ? "" : "expected no strings and reals in threes";
    // Radiance writes a broken object for 1 or 2 reals; its manual allows 0, 3, 6 or 7.
    case Rule::Mist: return n == 0 || (n >= 3 && n <= 7) ? "" : "expected 0 or 3 to 7 reals";
    case Rule::Text: return n >= 9 ? "" : "expected at least 9 reals";
    case Rule::Smoke:
        return !o.strings.empty() && o.integers.empty() && (n == 3 || n == 6 || n == 7)
                   ? ""
                   : "expected files, no integers and 3, 6 or 7 reals";
    default: return "";
    }
}

dvec3 triple(const std::vector<double>& r, size_t i) { return {r[i], r[i + 1], r[i + 2]}; }

void setTriple(std::vector<double>& r, size_t i, const dvec3& v) { r[i] = v.x, r[i + 1] = v.y, r[i + 2] = v.z; }

void movePoint(std::vector<double>& r, size_t i, const Transform& t) { setTriple(r, i, t.point(triple(r, i))); }

void turnVector(std::vector<double>& r, size_t i, const Transform& t) { setTriple(r, i, t.vector(triple(r, i))); }

// A polygon's normal follows its vertex order (right-hand rule); a mirror reverses that handedness, so the
// order is reversed to keep the normal on the mirrored side.
void movePolygon(std::vector<double>& r, const Transform& t, bool reverse) {
    std::vector<dvec3> vertices;
    for (size_t i = 0; i < r.size(); i += 3) vertices.push_back(t.point(triple(r, i)));
    if (reverse) std::reverse(vertices.begin(), vertices.end());
    for (size_t k = 0; k < vertices.size(); ++k) setTriple(r, 3 * k, vertices[k]);
}

// Transmittances per unit length (dielectric, interface): over a length scaled by s, t becomes t^(1/s).
void scaleTransmittance(std::vector<double>& r, size_t i, double scale) {
    for (size_t k = i; k < i + 3; ++k) r[k] = std::pow(r[k], 1 / scale);
}

// Mist names the light sources it scatters, "lamp" or "relay>lamp" (lamp relayed by a mirror or prism
// surface); all are surfaces, renamed like them.
std::string prefixedSources(const std::string& names, const std::string& prefix) {
    std::string out;
    for (size_t at = 0; at < names.size();) {
        size_t end = std::min(names.find('>', at), names.size() - 1) + 1;
        out += prefix + "." + names.substr(at, end - at);
        at = end;
    }
    return out;
}

// The transform travels with the object; "-i 1" first ends any -i in the object's own transform, which
// would otherwise repeat the one appended.
void appendTransform(std::vector<std::string>& strings, const std::vector<std::string>& words) {
    if (words.empty()) return;
    if (words[0] != "-i") strings.insert(strings.end(), {"-i", "1"});
    strings.insert(strings.end(), words.begin(), words.end());
}

void transformArguments(SceneObject& o, Rule rule, const ObjectTransform& how) {
    const Transform& t = how.transform;
    double s = std::abs(t.scale);
    std::vector<double>& r = o.reals;
    switch (rule) {
    case Rule::Keep: break;
    case Rule::AppendTransform: appendTransform(o.strings, how.words); break;
    case Rule::Source: turnVector(r, 0, t); break;
    case Rule::Sphere: movePoint(r, 0, t), r[3] *= s; break;
    case Rule::Polygon: movePolygon(r, t, t.mirrors() != how.invert); break;
    case Rule::Cone: movePoint(r, 0, t), movePoint(r, 3, t), r[6] *= s, r[7] *= s; break;
    case Rule::Cylinder: movePoint(r, 0, t), movePoint(r, 3, t), r[6] *= s; break;
    case Rule::Ring:
        movePoint(r, 0, t), turnVector(r, 3, t), r[6] *= s, r[7] *= s;
        if (how.invert) setTriple(r, 3, -triple(r, 3));  // the disk turned over
        break;
    case Rule::Glow: r[3] *= s; break;  // the radius of influence
    case Rule::Spotlight: turnVector(r, 4, t); break;
    case Rule::Dielectric: scaleTransmittance(r, 0, s); break;
    case Rule::Interface: scaleTransmittance(r, 0, s), scaleTransmittance(r, 4, s); break;
    case Rule::Mist:
        for (size_t k = 0; k < 3 && r.size() >= 3; ++k) r[k] /= s;  // extinction per unit length
        if (!how.prefix.empty())
            for (std::string& name : o.strings) name = prefixedSources(name, how.prefix);
        break;
    case Rule::Text: movePoint(r, 0, t), turnVector(r, 3, t), turnVector(r, 6, t); break;  // anchor, right, down
    // Placed by its grids' own transforms, which xform would have to rewrite (or carry) to move it.
    case Rule::Smoke:
        if (t.matrix != glm::dmat4(1.0)) throw Error(o.where, "cannot transform smoke '" + o.name + "' yet");
        break;
    }
}

// The type with the surface turned inside out (-I); planar surfaces turn by their vertex order or normal.
std::string invertedType(const std::string& type) {
    static const std::unordered_map<std::string, std::string> inverse = {
        {"sphere", "bubble"}, {"bubble", "sphere"}, {"cone", "cup"},
        {"cup", "cone"},      {"cylinder", "tube"}, {"tube", "cylinder"}};
    auto it = inverse.find(type);
    return it == inverse.end() ? type : it->second;
}

}  // namespace

void transformObject(ObjectText& text, const ObjectTransform& how) {
    SceneObject& o = text.object;
    std::optional<Rule> rule = ruleOf(o.type);
    if (!rule) throw Error(o.where, "unknown object type '" + o.type + "'");
    if (std::string why = misfit(o, *rule); !why.empty())
        throw Error(o.where, "bad " + o.type + " '" + o.name + "': " + why);
    transformArguments(o, *rule, how);
    if (isModifierType(o.type)) return;
    // Surfaces and volumes only: modifiers keep their names, which the surfaces refer to.
    if (!how.modifier.empty()) text.modifier = how.modifier;
    if (how.invert) o.type = invertedType(o.type);
    if (!how.prefix.empty()) o.name = how.prefix + "." + o.name;
}

}  // namespace brume
