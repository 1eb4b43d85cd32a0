#include "fds/case_geometry.h"

#include <algorithm>
#include <cctype>

#include "util/error.h"

namespace brume {

namespace {

// The boxes that make `a` less the box from `cutLo` to `cutHi`, in N dimensions (`lo(box)[k]` and `hi(box)[k]`
// its extents): `a` where they do not overlap, else up to 2N pieces, none where the cut covers it.
template <int N, class Box, class Extent, class Lo, class Hi>
std::vector<Box> less(const Box& a, const Extent& cutLo, const Extent& cutHi, Lo lo, Hi hi) {
    for (int k = 0; k < N; ++k)
        if (!(cutLo[k] < hi(a)[k] && cutHi[k] > lo(a)[k])) return {a};
    std::vector<Box> out;
    Box rest = a;
    for (int k = 0; k < N; ++k) {
        if (lo(rest)[k] < cutLo[k]) {
            Box below = rest;
            hi(below)[k] = cutLo[k];
            out.push_back(below);
            lo(rest)[k] = cutLo[k];
        }
        if (hi(rest)[k] > cutHi[k]) {
            Box above = rest;
            lo(above)[k] = cutHi[k];
            out.push_back(above);
            hi(rest)[k] = cutHi[k];
        }
    }
    return out;  // `rest` is inside the cut
}

std::vector<Bounds3> subtract(const Bounds3& a, const Bounds3& cut) {
    return less<3>(a, cut.lo, cut.hi, [](auto& b) -> auto& { return b.lo; }, [](auto& b) -> auto& { return b.hi; });
}

std::vector<CaseRectangle> subtract(const CaseRectangle& a, const std::array<double, 2>& lo, const std::array<double, 2>& hi) {
    return less<2>(a, lo, hi, [](auto& r) -> auto& { return r.lo; }, [](auto& r) -> auto& { return r.hi; });
}

// The two axes of a rectangle on a plane normal to `axis`, in increasing order.
std::array<int, 2> planeAxes(int axis) { return axis == 0 ? std::array{1, 2} : axis == 1 ? std::array{0, 2} : std::array{0, 1}; }

Bounds3 boxOf(const FdsGroup& g, bool flatAllowed) {
    std::optional<std::vector<double>> xb = g.numbers("XB", 6);
    if (!xb) throw Error(g.where + ": &" + g.name + " has no XB");
    const std::vector<double>& v = *xb;
    Bounds3 b{dvec3(v[0], v[2], v[4]), dvec3(v[1], v[3], v[5])};
    for (int k = 0; k < 3; ++k)
        if (b.lo[k] > b.hi[k] || (!flatAllowed && b.lo[k] == b.hi[k]))
            throw Error(g.where + ": &" + g.name + " XB: each lower bound must be below its upper one");
    return b;
}

// The sRGB colour of a SURF or VENT group (RGB=r,g,b 0-255, or COLOR by name), with a warning where the name is
// not known.
std::optional<std::array<double, 3>> colourOf(const FdsGroup& g, std::vector<std::string>& warnings) {
    if (std::optional<std::vector<double>> rgb = g.numbers("RGB", 3))
        return std::array<double, 3>{std::clamp((*rgb)[0] / 255, 0.0, 1.0), std::clamp((*rgb)[1] / 255, 0.0, 1.0),
                                     std::clamp((*rgb)[2] / 255, 0.0, 1.0)};
    if (std::optional<std::string> name = g.text("COLOR")) {
        if (std::optional<std::array<double, 3>> c = fdsColour(*name)) return c;
        warnings.push_back(g.where + ": &" + g.name + " COLOR '" + *name + "' is not a colour name known here: grey .5");
    }
    return std::nullopt;
}

}  // namespace

std::array<dvec3, 4> CaseRectangle::corners() const {
    const std::array<int, 2> uv = planeAxes(axis);
    auto point = [&](double u, double v) {
        dvec3 p(0);
        p[axis] = at, p[uv[0]] = u, p[uv[1]] = v;
        return p;
    };
    // (u, v) counter-clockwise faces +axis when u × v = +axis, which holds for (y, z) on x, (z, x) on y, (x, y)
    // on z: on y the increasing order (x, z) is the other way round.
    const bool ccw = (axis == 1) != (facing > 0);
    std::array<dvec3, 4> c = {point(lo[0], lo[1]), point(hi[0], lo[1]), point(hi[0], hi[1]), point(lo[0], hi[1])};
    if (!ccw) std::swap(c[1], c[3]);
    return c;
}

CaseRectangle boxFace(const Bounds3& box, int axis, bool high, bool outward, const std::string& surf,
                      const std::string& id) {
    const std::array<int, 2> uv = planeAxes(axis);
    return {axis, high ? box.hi[axis] : box.lo[axis], {box.lo[uv[0]], box.lo[uv[1]]}, {box.hi[uv[0]], box.hi[uv[1]]},
            high == outward ? 1 : -1, surf, id};
}

bool CaseGeometry::inside(const dvec3& p) const {
    return std::any_of(meshes.begin(), meshes.end(), [&](const Bounds3& b) { return b.contains(p); });
}

bool CaseGeometry::inSolid(const dvec3& p) const {
    return std::any_of(solids.begin(), solids.end(), [&](const CaseSolid& s) { return s.box.contains(p); });
}

CaseGeometry caseGeometry(const std::vector<FdsGroup>& groups) {
    CaseGeometry c;
    c.surfaces["INERT"] = {};
    c.surfaces["OPEN"] = {};
    std::vector<Bounds3> holes;
    std::vector<const FdsGroup*> obstructions, vents;
    for (const FdsGroup& g : groups) {
        if (g.name == "MESH") c.meshes.push_back(boxOf(g, false));
        else if (g.name == "HOLE") holes.push_back(boxOf(g, true));
        else if (g.name == "OBST") obstructions.push_back(&g);
        else if (g.name == "VENT") vents.push_back(&g);
        else if (g.name == "SURF") {
            std::optional<std::string> id = g.text("ID");
            if (!id) throw Error(g.where + ": &SURF has no ID");
            CaseSurface s;
            if (std::optional<std::array<double, 3>> rgb = colourOf(g, c.warnings)) s.rgb = *rgb, s.coloured = true;
            c.surfaces[*id] = s;
        }
    }
    if (c.meshes.empty()) throw Error("no &MESH: the case has no domain");
    for (const FdsGroup* g : obstructions) {
        std::vector<Bounds3> pieces = {boxOf(*g, true)};
        for (const Bounds3& hole : holes) {
            std::vector<Bounds3> left;
            for (const Bounds3& p : pieces)
                for (const Bounds3& q : subtract(p, hole)) left.push_back(q);
            pieces = std::move(left);
        }
        std::string surf = g->text("SURF_ID").value_or("INERT");
        if (!c.surfaces.count(surf)) {
            c.warnings.push_back(g->where + ": &OBST SURF_ID '" + surf + "' is no &SURF of the case: grey .5");
            c.surfaces[surf] = {};
        }
        for (const Bounds3& p : pieces)
            if (p.lo.x < p.hi.x && p.lo.y < p.hi.y && p.lo.z < p.hi.z) c.solids.push_back({p, surf, g->text("ID").value_or("")});
    }
    // The domain's walls: each mesh face less where another mesh touches it.
    for (size_t m = 0; m < c.meshes.size(); ++m)
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                const CaseRectangle face = boxFace(c.meshes[m], axis, side, false, "INERT", "");
                std::vector<CaseRectangle> left = {face};
                for (size_t n = 0; n < c.meshes.size(); ++n) {
                    const CaseRectangle touching = boxFace(c.meshes[n], axis, !side, true, "", "");
                    if (n == m || touching.at != face.at) continue;
                    std::vector<CaseRectangle> next;
                    for (const CaseRectangle& r : left)
                        for (const CaseRectangle& q : subtract(r, touching.lo, touching.hi)) next.push_back(q);
                    left = std::move(next);
                }
                for (const CaseRectangle& r : left) c.walls.push_back(r);
            }
    for (const FdsGroup* g : vents) {
        const Bounds3 b = boxOf(*g, true);
        int axis = -1;
        for (int k = 0; k < 3; ++k)
            if (b.lo[k] == b.hi[k]) axis = axis < 0 ? k : 3;
        const std::string surf = g->text("SURF_ID").value_or("INERT");
        if (axis < 0 || axis == 3) {
            c.warnings.push_back(g->where + ": &VENT is not a plane rectangle (one XB pair equal): left out");
            continue;
        }
        const std::array<int, 2> uv = planeAxes(axis);
        CaseRectangle r{axis, b.lo[axis], {b.lo[uv[0]], b.lo[uv[1]]}, {b.hi[uv[0]], b.hi[uv[1]]}, 1, surf,
                        g->text("ID").value_or("")};
        if (upperCase(surf) == "OPEN") {
            std::vector<CaseRectangle> walls;
            bool onWall = false;
            for (const CaseRectangle& w : c.walls) {
                if (w.axis != axis || w.at != r.at) {
                    walls.push_back(w);
                    continue;
                }
                std::vector<CaseRectangle> left = subtract(w, r.lo, r.hi);
                onWall = onWall || left.size() != 1 || left[0].lo != w.lo || left[0].hi != w.hi;
                walls.insert(walls.end(), left.begin(), left.end());
            }
            if (!onWall) c.warnings.push_back(g->where + ": &VENT OPEN on no wall of the domain: left out");
            c.walls = std::move(walls);
            r.facing = 1;
            c.openings.push_back(r);
            continue;
        }
        if (!c.surfaces.count(surf)) {
            c.warnings.push_back(g->where + ": &VENT SURF_ID '" + surf + "' is no &SURF of the case: grey .5");
            c.surfaces[surf] = {};
        }
        // Facing into the domain: away from the wall or solid it lies on (the side with space before it).
        dvec3 probe = (b.lo + b.hi) * 0.5;
        probe[axis] += 1e-3;
        r.facing = c.inside(probe) && !c.inSolid(probe) ? 1 : -1;
        c.vents.push_back(r);
    }
    for (CaseRectangle& w : c.walls) w.surf = "INERT";
    return c;
}

std::optional<std::array<double, 3>> fdsColour(const std::string& name) {
    // X11's values of the names FDS input files use most (FDS takes X11's names, spaces between words).
    static const std::map<std::string, std::array<int, 3>> kColours = {
        {"BLACK", {0, 0, 0}},          {"WHITE", {255, 255, 255}},     {"GRAY", {190, 190, 190}},
        {"GREY", {190, 190, 190}},     {"DIM GRAY", {105, 105, 105}},  {"DIM GREY", {105, 105, 105}},
        {"DARK GRAY", {169, 169, 169}}, {"LIGHT GRAY", {211, 211, 211}}, {"SILVER", {192, 192, 192}},
        {"GAINSBORO", {220, 220, 220}}, {"SLATE GRAY", {112, 128, 144}}, {"RED", {255, 0, 0}},
        {"GREEN", {0, 255, 0}},        {"BLUE", {0, 0, 255}},          {"YELLOW", {255, 255, 0}},
        {"ORANGE", {255, 165, 0}},     {"BROWN", {165, 42, 42}},       {"TAN", {210, 180, 140}},
        {"BEIGE", {245, 245, 220}},    {"IVORY", {255, 255, 240}},     {"KHAKI", {240, 230, 140}},
        {"WHEAT", {245, 222, 179}},    {"BURLY WOOD", {222, 184, 135}}, {"SIENNA", {160, 82, 45}},
        {"CHOCOLATE", {210, 105, 30}}, {"MAROON", {176, 48, 96}},      {"PINK", {255, 192, 203}},
        {"CYAN", {0, 255, 255}},       {"MAGENTA", {255, 0, 255}},     {"NAVY", {0, 0, 128}},
        {"OLIVE DRAB", {107, 142, 35}}, {"FOREST GREEN", {34, 139, 34}}, {"SKY BLUE", {135, 206, 235}},
        {"STEEL BLUE", {70, 130, 180}}, {"BRICK", {156, 102, 31}},     {"LINEN", {250, 240, 230}},
        {"SANDY BROWN", {244, 164, 96}}, {"INDIAN RED", {205, 92, 92}}, {"FIREBRICK", {178, 34, 34}},
    };
    auto it = kColours.find(upperCase(name));
    if (it == kColours.end()) return std::nullopt;
    return std::array<double, 3>{it->second[0] / 255.0, it->second[1] / 255.0, it->second[2] / 255.0};
}

}  // namespace brume
