#include "visibility/study_checks.h"

#include <glm/geometric.hpp>

namespace brume {

namespace {

std::string some(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size() && i < 3; ++i) out += (i ? ", " : "") + names[i];
    return names.size() > 3 ? out + ", ..." : out;
}

bool inDomain(const std::vector<SmokeDescription>& smoke, const dvec3& p, bool& anyDomain) {
    for (const SmokeDescription& s : smoke)
        for (const KeyFrame& f : s.frames->keyFrames())
            for (const Bounds3& b : f.grid.coverage().domain()) {
                anyDomain = true;
                if (b.contains(p)) return true;
            }
    return false;
}

}  // namespace

bool insideSolid(const SceneGeometry& geometry, const dvec3& p) {
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            dvec3 dir(0);
            dir[axis] = sign;
            std::optional<SurfaceHit> hit = geometry.intersect(Ray(p, dir));
            if (!hit || !(glm::dot(hit->normal, dir) > 0)) return false;
        }
    return true;
}

std::vector<std::string> studyWarnings(const VisibilityStudy& study, const SceneGeometry& geometry,
                                       const std::vector<SmokeDescription>& smoke) {
    std::vector<std::string> out;
    const std::vector<Observer>& eyes = study.observers();
    for (const StudySign& s : study.signs()) {
        const Sign& sign = s.sign;
        const bool seen = std::any_of(eyes.begin(), eyes.end(), [&](const Observer& o) { return facing(sign, o.eye); });
        const dvec3& n = sign.shape.normal;
        if (!seen)
            out.push_back("sign '" + sign.name + "' faces away from every eye (its front faces (" + std::to_string(n.x) +
                          ", " + std::to_string(n.y) + ", " + std::to_string(n.z) +
                          "), as its polygon's vertex order says: reversed?)");
        if (insideSolid(geometry, sign.centre + 0.01 * n))
            out.push_back("sign '" + sign.name + "' lies inside a solid (its front, 1 cm before it, is enclosed)");
    }
    std::vector<std::string> inside, outside;
    bool anyDomain = false;
    for (const Observer& o : eyes) {
        if (insideSolid(geometry, o.eye)) inside.push_back(o.name);
        if (!inDomain(smoke, o.eye, anyDomain)) outside.push_back(o.name);
    }
    const std::string of = " of " + std::to_string(eyes.size()) + " eyes ";
    if (!inside.empty())
        out.push_back(std::to_string(inside.size()) + of + "lie inside solids (" + some(inside) +
                      "): their sight lines start in a wall");
    if (anyDomain && !outside.empty())
        out.push_back(std::to_string(outside.size()) + of + "lie outside the smoke's simulated domain (" + some(outside) + ")");
    return out;
}

}  // namespace brume
