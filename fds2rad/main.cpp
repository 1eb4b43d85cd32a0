// fds2rad: an FDS case's building as a Radiance scene, and signs placed by position, size and facing (see
// man/fds2rad.1).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "fds/case_geometry.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"
#include "visibility/line_words.h"
#include "visibility/sign_layout.h"

using namespace brume;

namespace {

struct Options {
    std::string materials;  // a table of reflectances by SURF ID
    std::string signs;      // sign placements
    std::string signList;   // where vismap's sign list goes
};

const std::string kUsage = "usage: fds2rad [-m materials.txt] [-s signs.txt -S vismap_signs.txt] case.fds > building.rad\n";

OptionTable makeTable(Options& o) {
    OptionTable t;
    t.add("-m", 1, "reflectances by SURF ID: lines 'SURF_ID r g b' or 'SURF_ID rho'", [&o](const auto& a) { o.materials = a[0]; });
    t.add("-s", 1, "signs by position: 'name x y z front_x front_y front_z width height kind L|rho [C]'",
          [&o](const auto& a) { o.signs = a[0]; });
    t.add("-S", 1, "the sign list for vismap -S, written with -s", [&o](const auto& a) { o.signList = a[0]; });
    return t;
}

// sRGB (a display colour, 0-1) to linear reflectance.
double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// A Radiance name from an FDS ID: its letters, digits and '_' kept, the rest '_'.
std::string radianceName(const std::string& id) {
    std::string n;
    for (char c : id) n += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ? c : '_';
    return n.empty() ? "unnamed" : n;
}

// Reflectances given by the user, by SURF ID: 'ID r g b' or 'ID rho'.
std::map<std::string, std::array<double, 3>> readMaterials(const std::string& path) {
    std::map<std::string, std::array<double, 3>> out;
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot be opened");
    forEachWordLine(in, path, [&](const std::vector<std::string>& w, const std::string& where) {
        if (w.size() != 2 && w.size() != 4) throw Error(where + ": expected 'SURF_ID r g b' or 'SURF_ID rho'");
        std::array<double, 3> rho;
        for (size_t k = 0; k < 3; ++k) {
            rho[k] = realWord(w[w.size() == 2 ? 1 : 1 + k], where, "reflectance");
            if (!(rho[k] >= 0 && rho[k] <= 1)) throw Error(where + ": a reflectance is between 0 and 1");
        }
        out[w[0]] = rho;
    });
    return out;
}

void polygon(const std::string& material, const std::string& name, const std::array<dvec3, 4>& c) {
    std::printf("%s polygon %s\n0\n0\n12", material.c_str(), name.c_str());
    for (const dvec3& p : c) std::printf("  %.9g %.9g %.9g", p.x, p.y, p.z);
    std::printf("\n");
}

void writeSurfaces(const CaseGeometry& g, const std::map<std::string, std::array<double, 3>>& given) {
    std::printf("\n# Surfaces: plastic of each SURF's display colour as a linear reflectance (sRGB decoded), or as given (-m)\n");
    for (const auto& [id, s] : g.surfaces) {
        if (id == "OPEN") continue;
        auto own = given.find(id);
        std::array<double, 3> rho;
        for (int k = 0; k < 3; ++k) rho[size_t(k)] = own != given.end() ? own->second[size_t(k)] : linear(s.rgb[size_t(k)]);
        if (own != given.end()) std::printf("# %s: as given\n", id.c_str());
        else if (!s.coloured) std::printf("# %s: no colour, grey .5 in sRGB\n", id.c_str());
        std::printf("void plastic surf_%s\n0\n0\n5 %.4g %.4g %.4g 0 0\n", radianceName(id).c_str(), rho[0], rho[1], rho[2]);
    }
}

void writeBuilding(const CaseGeometry& g) {
    std::printf("\n# The domain's walls (FDS's inert boundary), facing in; OPEN vents left open\n");
    for (size_t i = 0; i < g.walls.size(); ++i) polygon("surf_INERT", "domain_" + std::to_string(i), g.walls[i].corners());
    std::printf("\n# Obstructions less their holes, faces out\n");
    for (size_t i = 0; i < g.solids.size(); ++i) {
        const CaseSolid& s = g.solids[i];
        const std::string name = radianceName(s.id.empty() ? "obst" : s.id) + "_" + std::to_string(i);
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                polygon("surf_" + radianceName(s.surf), name + "_" + "xyz"[axis] + (side ? "+" : "-"),
                        boxFace(s.box, axis, side, true, s.surf, s.id).corners());
            }
    }
    std::printf("\n# Vents (burners and other surfaces), 1 mm into the domain\n");
    for (size_t i = 0; i < g.vents.size(); ++i) {
        CaseRectangle r = g.vents[i];
        r.at += 1e-3 * r.facing;
        polygon("surf_" + radianceName(r.surf), radianceName(r.id.empty() ? "vent" : r.id) + "_" + std::to_string(i), r.corners());
    }
}

// What is likely wrong with a sign's placement.
void checkSigns(const std::vector<SignPlacement>& signs, const CaseGeometry& g) {
    for (const SignPlacement& s : signs) {
        if (!g.inside(s.centre)) warn(s.where + ": sign '" + s.name + "' lies outside the case's domain");
        if (g.inSolid(s.centre + 0.01 * s.front))
            warn(s.where + ": sign '" + s.name + "' faces into a solid (1 cm before it is an obstruction)");
    }
}

// vismap's sign list (-S) of the signs placed.
void writeSignList(const std::vector<SignPlacement>& signs, const std::string& path) {
    std::ofstream out(path);
    out << "# polygon kind C (fds2rad -s)\n";
    for (const SignPlacement& s : signs)
        out << radianceName(s.name) << ' ' << signKindName(s.kind) << ' ' << s.jinConstant << "\n";
    if (!out) throw Error(path + ": cannot be written");
}

// The signs: polygons 5 mm before their walls, each of its own material.
void writeSigns(const std::vector<SignPlacement>& signs) {
    std::printf("\n# Signs (fds2rad -s), 5 mm before their walls\n");
    for (const SignPlacement& s : signs) {
        SignPlacement placed = s;
        placed.centre += 0.005 * s.front;
        const std::string material = "sign_" + radianceName(s.name);
        if (s.kind == SignKind::Emitting) {
            // An exit sign's green, scaled to its luminance: Radiance's 179 lm/W times 0.265 R + 0.670 G + 0.065 B.
            const double green[3] = {0.12, 1.2, 0.2}, y = 0.265 * green[0] + 0.670 * green[1] + 0.065 * green[2];
            const double k = s.shows / (179 * y);
            std::printf("void glow %s\n0\n0\n4 %.6g %.6g %.6g 0\n", material.c_str(), k * green[0], k * green[1], k * green[2]);
        } else {
            std::printf("void plastic %s\n0\n0\n5 %.4g %.4g %.4g 0 0\n", material.c_str(), s.shows, s.shows, s.shows);
        }
        polygon(material, radianceName(s.name), placed.corners());
    }
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t first = table.parse(args);
    if (args.size() != first + 1) throw UsageError("expected one .fds file", kUsage + table.usage());
    if (!o.signList.empty() && o.signs.empty()) throw UsageError("-S: the sign list comes from signs given by -s", kUsage);
    const std::string path = args[first];
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot be opened");
    CaseGeometry g = caseGeometry(readFdsInput(in, path));
    for (const std::string& w : g.warnings) warn(w);
    std::map<std::string, std::array<double, 3>> given;
    if (!o.materials.empty()) given = readMaterials(o.materials);
    std::vector<SignPlacement> signs;
    if (!o.signs.empty()) {
        std::ifstream s(o.signs);
        if (!s) throw Error(o.signs + ": cannot be opened");
        signs = readSignPlacements(s, o.signs);
        checkSigns(signs, g);
        if (!o.signList.empty()) writeSignList(signs, o.signList);  // before the scene: an error leaves no scene
    }
    std::vector<std::string> command(argv, argv + argc);
    command[0] = programName();
    std::printf("# %s\n# the building of %s: %zu meshes, %zu obstruction boxes (holes cut), %zu wall pieces of the domain, "
                "%zu openings, %zu vents\n",
                commandLine(command).c_str(), path.c_str(), g.meshes.size(), g.solids.size(), g.walls.size(),
                g.openings.size(), g.vents.size());
    writeSurfaces(g, given);
    writeBuilding(g);
    if (!signs.empty()) writeSigns(signs);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
