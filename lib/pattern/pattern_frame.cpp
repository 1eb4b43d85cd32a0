#include "pattern/pattern_frame.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace brume {

PatternFrame PatternFrame::fromArguments(const SceneObject& o, std::span<const std::string> args) {
    auto first = std::find_if(args.begin(), args.end(), [](const std::string& a) { return isTransformOption(a); });
    std::span<const std::string> xf(first, args.end());
    ParsedTransform t = parseTransform(xf);
    if (t.used != xf.size()) throw Error(o.where, "bad transform for " + o.type + " \"" + o.name + "\"");
    // Only the size of the scale matters to patterns (Radiance's getfunc makes it positive).
    Transform toWorld{t.transform.matrix, std::abs(t.transform.scale)};
    return PatternFrame{toWorld, toWorld.inverse()};
}

Transform PatternFrame::fromWorld(const PatternHit& hit) const {
    return hit.object ? hit.object->toObject.then(toPattern) : toPattern;
}

// Radiance's chanvalue(): directions and normals turned into the pattern's axes and kept unit length,
// points moved, distances scaled; S, T, I, J, K describe the world-to-pattern map itself.
void PatternFrame::channels(const PatternHit& hit, cal::Channels& c) const {
    Transform m = fromWorld(hit);
    double s = std::abs(m.scale);
    dvec3 d = m.vector(hit.dir) / s, n = m.vector(hit.normal) / s, p = m.point(hit.point);
    c[cal::Dx] = d.x, c[cal::Dy] = d.y, c[cal::Dz] = d.z;
    c[cal::Nx] = n.x, c[cal::Ny] = n.y, c[cal::Nz] = n.z;
    c[cal::Px] = p.x, c[cal::Py] = p.y, c[cal::Pz] = p.z;
    c[cal::T] = hit.distance * s;
    c[cal::Ts] = hit.distance * s;
    c[cal::Rdot] = std::clamp(-glm::dot(hit.dir, hit.normal), -1.0, 1.0);
    c[cal::S] = s;
    c[cal::Tx] = m.matrix[3][0], c[cal::Ty] = m.matrix[3][1], c[cal::Tz] = m.matrix[3][2];
    for (int axis = 0; axis < 3; ++axis) {
        dvec3 unit = dvec3(m.matrix[axis]) / s;  // the image of world axis `axis` in pattern coordinates
        c[cal::Ix + 3 * axis] = unit.x, c[cal::Iy + 3 * axis] = unit.y, c[cal::Iz + 3 * axis] = unit.z;
    }
    c[cal::Lu] = hit.u, c[cal::Lv] = hit.v;
}

dvec3 PatternFrame::toWorldVector(const dvec3& d, const PatternHit& hit) const {
    Transform m = hit.object ? toWorld.then(hit.object->toWorld) : toWorld;
    return m.vector(d) / std::abs(m.scale);
}

dvec3 PatternFrame::toPatternDirection(const dvec3& d, const PatternHit& hit) const {
    Transform m = fromWorld(hit);
    return m.vector(d) / std::abs(m.scale);
}

}  // namespace brume
