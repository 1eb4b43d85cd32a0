// fds2vdb: an FDS case's smoke as OpenVDB grids, one file per instant, and the `smoke` object that reads them
// (see man/fds2vdb.1).
#include <openvdb/openvdb.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "fds/fds_quantity.h"
#include "fds/smv_index.h"
#include "medium/data_coverage.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"

using namespace brume;

namespace {

struct Options {
    std::string quantity = "SOOT DENSITY";
    std::vector<double> instants;  // none: every frame
    std::string prefix;            // of the files written; the case's CHID and the quantity by default
    bool flames = false;           // TEMPERATURE too, as the grid "temperature" (K)
    bool grey = false;             // soot's K in every band, not its spectrum
    std::optional<SliceLayer> layer;  // meshes without 3D data filled from a 2D slice over these heights
};

const std::string kUsage = "usage: fds2vdb [options] case.smv > smoke.rad\n";

// The reals of a comma-separated list given to `option`.
std::vector<double> realsFrom(const std::string& option, const std::string& list) {
    std::vector<double> out;
    std::stringstream in(list);
    for (std::string word; std::getline(in, word, ',');) out.push_back(toReal(option, word));
    return out;
}

std::vector<double> instantsFrom(const std::string& list) {
    std::vector<double> out = realsFrom("-t", list);
    if (out.empty() || !std::is_sorted(out.begin(), out.end()) ||
        std::adjacent_find(out.begin(), out.end()) != out.end())
        throw UsageError("-t: instants must increase (e.g. -t 30,60,90)", kUsage);
    return out;
}

OptionTable makeTable(Options& o) {
    OptionTable t;
    t.add("-q", 1, "the quantity (FDS's label; default SOOT DENSITY)", [&o](const auto& a) { o.quantity = a[0]; });
    t.add("-t", 1, "instants t1,t2,... in seconds (default: every frame)",
          [&o](const auto& a) { o.instants = instantsFrom(a[0]); });
    t.add("-o", 1, "prefix of the files written (default CHID_quantity)", [&o](const auto& a) { o.prefix = a[0]; });
    t.addBool("-f", o.flames, "also TEMPERATURE, in kelvin, as the grid 'temperature' (flames)");
    t.addBool("-g", o.grey, "soot's extinction grey, its 633 nm value in every band (default: soot's spectrum)");
    t.add("-l", 1, "z0,z1: meshes without 3D data take a horizontal 2D slice's values from z0 to z1 (m)",
          [&o](const auto& a) {
              const std::vector<double> z = realsFrom("-l", a[0]);
              if (z.size() != 2 || !(z[0] < z[1])) throw UsageError("-l: expected two heights z0,z1 with z0 < z1", kUsage);
              o.layer = SliceLayer{z[0], z[1]};
          });
    return t;
}

// "SOOT DENSITY" -> "soot_density".
std::string fileWord(const std::string& quantity) {
    std::string w;
    for (char c : quantity) w += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
    return w;
}

// Where the case has data: the meshes' boxes (the domain), those of the meshes read (a layer's heights only for a
// mesh filled from a slice), and in words which mesh gave what.
struct Coverage {
    std::vector<Bounds3> domain, data;
    std::string note;
};

Bounds3 meshBox(const FdsMesh& m) {
    return {glm::dvec3(m.nodes[0].front(), m.nodes[1].front(), m.nodes[2].front()),
            glm::dvec3(m.nodes[0].back(), m.nodes[1].back(), m.nodes[2].back())};
}

Coverage coverageOf(const SmvIndex& smv, const FdsQuantity& q, const std::optional<SliceLayer>& layer) {
    Coverage c;
    std::string none;
    for (size_t m = 0; m < smv.meshes.size(); ++m) {
        Bounds3 box = meshBox(smv.meshes[m]);
        c.domain.push_back(box);
        const std::string name = "mesh " + std::to_string(m + 1) + " (" + smv.meshes[m].id + ")";
        switch (q.meshSources()[m]) {
            case MeshSource::None: none += (none.empty() ? "" : ", ") + std::to_string(m + 1); continue;
            case MeshSource::Layer: box.lo.z = std::max(box.lo.z, layer->lo), box.hi.z = std::min(box.hi.z, layer->hi); break;
            case MeshSource::Volume: break;
        }
        c.data.push_back(box);
        c.note += (c.note.empty() ? "" : "; ") + name + ": " + q.meshSourceNotes()[m];
    }
    if (!none.empty()) c.note += (c.note.empty() ? "" : "; ") + ("no data in mesh " + none);
    return c;
}

openvdb::FloatGrid::Ptr gridOf(const LatticeVoxels& v, const std::string& name) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preScale(openvdb::Vec3d(v.spacing.x, v.spacing.y, v.spacing.z));
    m.postTranslate(openvdb::Vec3d(v.origin.x, v.origin.y, v.origin.z));
    grid->setTransform(openvdb::math::Transform::createLinearTransform(m));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->setName(name);
    auto access = grid->getAccessor();
    for (const auto& [index, value] : v.values) access.setValue(openvdb::Coord(index.x, index.y, index.z), value);
    grid->pruneGrid();
    return grid;
}

// The smoke object's reals: extinction per unit of the values (soot's mass extinction coefficient for kg/m³,
// the case's own if its 3D smoke files say, else FDS's 8700 m²/kg; 1 for an extinction coefficient), and an
// albedo and g of soot in the visible, which FDS does not compute.
void printOptics(const SmvIndex& smv, const std::string& units) {
    double k = 1;
    if (units == "kg/m3") {
        k = 8700;
        for (const FdsFile& f : smv.files)
            if (f.kind == FdsFile::Kind::Smoke3d && f.quantity == "SOOT DENSITY" && f.massExtinction > 0)
                k = f.massExtinction;
    } else if (units != "1/m") {
        warn("values in " + units + " are no density: the smoke object's extinction per unit (1) is to be set");
    }
    std::printf("\n0\n7 %g %g %g  .2 .2 .2  .6\n", k, k, k);
}

void warnAll(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) warn(w);
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::vector<std::string> args(argv + 1, argv + argc);
    size_t first = table.parse(args);
    if (args.size() != first + 1) throw UsageError("expected one .smv file", kUsage + table.usage());
    const std::string smvPath = args[first];
    SmvIndex smv = readSmv(smvPath);
    FdsQuantity quantity(smv, o.quantity, o.instants, o.layer);
    warnAll(quantity.warnings());
    std::optional<FdsQuantity> temperature;
    if (o.flames) {
        temperature.emplace(smv, "TEMPERATURE", o.instants.empty() ? quantity.times() : o.instants);
        warnAll(temperature->warnings());
    }
    const std::vector<double> instants = o.instants.empty() ? quantity.times() : o.instants;
    const std::string prefix = o.prefix.empty() ? smv.chid + "_" + fileWord(o.quantity) : o.prefix;
    const Coverage coverage = coverageOf(smv, quantity, o.layer);
    openvdb::initialize();
    std::vector<std::string> files;
    for (double t : instants) {
        char name[64];
        std::snprintf(name, sizeof name, "_%08.3f.vdb", t);
        openvdb::GridPtrVec grids;
        openvdb::FloatGrid::Ptr density = gridOf(quantity.at(t), "density");
        density->insertMeta("brume:domain", openvdb::StringMetadata(DataCoverage::format(coverage.domain)));
        density->insertMeta("brume:data", openvdb::StringMetadata(DataCoverage::format(coverage.data)));
        density->insertMeta("brume:data_note", openvdb::StringMetadata(coverage.note));
        grids.push_back(density);
        if (temperature) grids.push_back(gridOf(temperature->at(t), "temperature"));
        const std::string path = prefix + name;
        const std::string part = path + ".part";  // a file half written is never taken for a whole one
        openvdb::io::File(part).write(grids);
        std::filesystem::rename(part, path);
        files.push_back(path);
    }
    std::vector<std::string> command(argv, argv + argc);
    command[0] = programName();
    std::printf("# %s\n# '%s' (%s) of %s from its %s\n# data: %s\n"
                "# extinction per unit (at 633 nm), albedo and g: soot scatters about a fifth of what it takes, forward\n",
                commandLine(command).c_str(), o.quantity.c_str(),
                quantity.units().c_str(), smvPath.c_str(), quantity.source().c_str(), coverage.note.c_str());
    // Soot (its mass or its extinction): FDS's K is for 633 nm, and soot's grows toward the blue.
    const bool soot = !o.grey && (quantity.units() == "kg/m3" || quantity.units() == "1/m");
    std::printf("void smoke %s\n%zu%s%s", prefix.substr(prefix.find_last_of('/') + 1).c_str(),
                (files.size() == 1 ? 1 : 2 * files.size()) + (o.flames ? 1 : 0) + (soot ? 1 : 0),
                o.flames ? " temperature=temperature" : "", soot ? " extinction=soot" : "");
    if (files.size() == 1) std::printf(" %s", files[0].c_str());
    else
        for (size_t i = 0; i < files.size(); ++i) std::printf(" %.9g %s", instants[i], files[i].c_str());
    printOptics(smv, quantity.units());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
