#include "fds/fds_quantity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <glm/common.hpp>

#include "fds/plot3d_file.h"
#include "fds/slice_file.h"
#include "fds/smoke3d16_file.h"
#include "fds/smoke3d_file.h"
#include "util/error.h"

namespace brume {

namespace {

// FDS's default mass extinction coefficient of soot (m²/kg), for 3D smoke files whose entry does not give one.
constexpr double kSootMassExtinction = 8700;

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

// Cell widths of a mesh along each axis; Error where they are not all equal (a stretched mesh).
glm::dvec3 uniformSpacing(const SmvIndex& smv, int mesh) {
    const FdsMesh& m = smv.meshes[size_t(mesh)];
    glm::dvec3 d;
    for (int a = 0; a < 3; ++a) {
        const std::vector<double>& n = m.nodes[a];
        d[a] = (n.back() - n.front()) / double(n.size() - 1);
        for (size_t i = 0; i < n.size(); ++i)
            if (std::abs(n[i] - (n.front() + double(i) * d[a])) > 1e-4 * d[a] + 1e-5)  // the .smv prints 5 decimals
                throw Error(smv.path + ": mesh " + std::to_string(mesh + 1) + " (" + m.id +
                            ") is stretched: only meshes of even cells are imported");
    }
    return d;
}

std::string seconds(double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g s", t);
    return text;
}

// Which frames of a file to keep: all without `instants`, else for each instant the last at or before it and the
// first at or after it. `read(wanted)` reads the file keeping what `wanted` says: a first pass, keeping
// nothing, lists the frames' times.
// Error "path: …" where an instant lies outside the file's frames.
template <typename Read>
std::function<bool(double)> framesAround(const std::vector<double>& instants, const std::string& path, Read read) {
    if (instants.empty()) return nullptr;
    std::vector<double> times;
    read([&](double t) { return times.push_back(t), false; });
    std::vector<double> keep;
    for (double instant : instants) {
        if (times.empty() || instant < times.front() || instant > times.back())
            throw Error(path + ": no frame around " + seconds(instant) + ": the file holds " +
                        (times.empty() ? "none" : seconds(times.front()) + " to " + seconds(times.back())));
        auto later = std::lower_bound(times.begin(), times.end(), instant);
        if (later != times.end()) keep.push_back(*later);
        if (later != times.begin() && (later == times.end() || *later != instant)) keep.push_back(*std::prev(later));
    }
    return [keep](double t) { return std::find(keep.begin(), keep.end(), t) != keep.end(); };
}

}  // namespace

namespace {

std::string metres(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g m", x);
    return text;
}

// FDS writes a smoke's optical density as K / 2.3, not K / ln 10: 2.3 × OD is its K exactly (ln 10
// would give 0.11 % more).
constexpr double kOpticalDensityFactor = 2.3;

// The quantity's value per unit of a slice's quantity `from`, to fill a layer with: 1 for the quantity itself,
// else between soot's density, extinction coefficient and optical density (K = 2.3 × OD = K_m × ρ); none for
// anything else.
std::optional<double> layerScale(const std::string& quantity, const std::string& from, double massExtinction) {
    if (from == quantity) return 1.0;
    auto perExtinction = [&](const std::string& q) -> std::optional<double> {  // K per unit of q
        if (q == "SOOT EXTINCTION COEFFICIENT" || q == "EXTINCTION COEFFICIENT") return 1.0;
        if (q == "SOOT OPTICAL DENSITY" || q == "OPTICAL DENSITY") return kOpticalDensityFactor;
        if (q == "SOOT DENSITY") return massExtinction;
        return std::nullopt;
    };
    std::optional<double> target = perExtinction(quantity), source = perExtinction(from);
    if (!target || !source) return std::nullopt;
    return *source / *target;
}

// The height of a horizontal slice's plane: its cells' centres (cell-centred) or its nodes.
double planeHeight(const SmvIndex& smv, const FdsFile& f) {
    const std::vector<double>& z = smv.meshes[size_t(f.mesh)].nodes[2];
    const size_t k = size_t(f.range[4]);
    return f.cellCentred && k > 0 ? 0.5 * (z[k - 1] + z[k]) : z[k];
}

}  // namespace

FdsQuantity::FdsQuantity(const SmvIndex& smv, const std::string& quantity, const std::vector<double>& instants,
                         const std::optional<SliceLayer>& layer) {
    auto volumeSlice = [&](const FdsFile& f) {
        return f.kind == FdsFile::Kind::Slice && f.cellCentred && f.volume() && f.quantity == quantity;
    };
    // 3D smoke files: of any quantity where FDS wrote their 16-bit twins (.s16), else soot's 8-bit opacities.
    auto smoke3d = [&](const FdsFile& f) {
        return f.kind == FdsFile::Kind::Smoke3d && f.quantity == quantity &&
               (quantity == "SOOT DENSITY" || !smoke3d16Beside(f.path).empty());
    };
    auto present = [&](const FdsFile& f) { return fileExists(f.path) || !smoke3d16Beside(f.path).empty(); };
    bool slices = std::any_of(smv.files.begin(), smv.files.end(), [&](const FdsFile& f) {
        return volumeSlice(f) && fileExists(f.path);
    });
    bool soot3d = !slices && std::any_of(smv.files.begin(), smv.files.end(), [&](const FdsFile& f) {
        return smoke3d(f) && present(f);
    });
    double massExtinction = kSootMassExtinction;
    for (const FdsFile& f : smv.files)
        if (f.kind == FdsFile::Kind::Smoke3d && f.quantity == "SOOT DENSITY" && f.massExtinction > 0)
            massExtinction = f.massExtinction;
    // Plot3D files: of the quantity, or of soot's extinction for its density (over K_m).
    auto plot3d = [&](const FdsFile& f) {
        return f.kind == FdsFile::Kind::Plot3d && layerScale(quantity, f.quantity, massExtinction).has_value();
    };
    bool p3d = !slices && !soot3d && std::any_of(smv.files.begin(), smv.files.end(), [&](const FdsFile& f) {
        return plot3d(f) && fileExists(f.path);
    });
    source_ = slices ? "cell-centred 3D slices" : soot3d ? "3D smoke files" : p3d ? "Plot3D files" : "";
    const size_t meshCount = smv.meshes.size();
    meshSources_.assign(meshCount, MeshSource::None);
    meshNotes_.assign(meshCount, "");
    std::vector<std::string> absent(meshCount);  // a file of the mesh listed in the index, not there
    std::vector<const FdsFile*> chosen;           // one file per mesh
    for (const FdsFile& f : smv.files) {
        if (source_.empty() || !(slices ? volumeSlice(f) : soot3d ? smoke3d(f) : plot3d(f)) ||
            meshSources_[size_t(f.mesh)] != MeshSource::None)
            continue;
        if (!present(f)) {
            absent[size_t(f.mesh)] = f.path;
            continue;
        }
        chosen.push_back(&f);
        meshSources_[size_t(f.mesh)] = MeshSource::Volume;
        meshNotes_[size_t(f.mesh)] = slices  ? source_
                                    : p3d ? "Plot3D files ('" + f.quantity + "')"
                                    : smoke3d16Beside(f.path).empty() ? "3D smoke files (8-bit opacities)"
                                                                      : "16-bit 3D smoke files (.s16)";
    }
    // The layer's slices: per mesh without 3D data, the horizontal one in the layer nearest its middle.
    std::vector<std::pair<const FdsFile*, double>> layers(meshCount, {nullptr, 0.0});
    if (layer)
        for (const FdsFile& f : smv.files) {
            const size_t m = size_t(f.mesh);
            if (f.kind != FdsFile::Kind::Slice || meshSources_[m] != MeshSource::None || f.range[4] != f.range[5] ||
                f.range[0] == f.range[1] || f.range[2] == f.range[3] || !fileExists(f.path))
                continue;
            std::optional<double> scale = layerScale(quantity, f.quantity, massExtinction);
            const double z = planeHeight(smv, f), middle = 0.5 * (layer->lo + layer->hi);
            if (!scale || z < layer->lo || z > layer->hi) continue;
            if (!layers[m].first || std::abs(z - middle) < std::abs(planeHeight(smv, *layers[m].first) - middle))
                layers[m] = {&f, *scale};
        }
    const bool anyLayer = std::any_of(layers.begin(), layers.end(), [](const auto& l) { return l.first != nullptr; });
    if (chosen.empty() && !anyLayer) {
        std::string have;
        for (const FdsFile& f : smv.files)
            if ((f.kind == FdsFile::Kind::Smoke3d || (f.cellCentred && f.volume())) && fileExists(f.path) &&
                have.find("'" + f.quantity + "'") == std::string::npos)
                have += (have.empty() ? "" : ", ") + ("'" + f.quantity + "'");
        throw Error(smv.path + ": no cell-centred 3D slice" + (quantity == "SOOT DENSITY" ? " or 3D smoke file" : "") +
                    " of '" + quantity + "' (the case has " + (have.empty() ? "none of either" : have) + ")" +
                    (layer ? ", nor a horizontal 2D slice of it (or of soot's extinction or optical density) within "
                             "the layer's heights"
                           : ""));
    }
    if (!chosen.empty()) {
        std::vector<int> meshes;
        for (const FdsFile* f : chosen) meshes.push_back(f->mesh);
        setLattice(smv, meshes, slices);
    } else {
        std::vector<int> meshes;
        for (const auto& [f, scale] : layers)
            if (f) meshes.push_back(f->mesh);
        setLattice(smv, meshes, true);
    }
    for (const FdsFile* f : chosen) {
        if (slices) addSlice(smv, *f, instants);
        else if (p3d) addPlot3d(smv, *f, *layerScale(quantity, f->quantity, massExtinction), instants);
        else addSmoke3d(smv, *f, instants);
        if (units_.empty()) units_ = f->units;
    }
    for (const auto& [f, scale] : layers)  // only layers: soot's units, or the slices' own quantity's
        if (units_.empty() && f)
            units_ = quantity == "SOOT DENSITY" ? "kg/m3" : scale == 1 && f->quantity == quantity ? f->units : "1/m";
    for (size_t m = 0; m < meshCount; ++m)
        if (layers[m].first) {
            meshNotes_[m] = addLayer(smv, *layers[m].first, *layer, layers[m].second, instants);
            meshSources_[m] = MeshSource::Layer;
        }
    for (size_t m = 0; m < meshCount; ++m)
        if (meshSources_[m] == MeshSource::None)
            warnings_.push_back(smv.path + ": mesh " + std::to_string(m + 1) + " (" + smv.meshes[m].id + ") has no " +
                                (source_.empty() ? "3D data" : source_) + " of '" + quantity + "'" +
                                (absent[m].empty() ? "" : " (" + absent[m] + " is listed but absent)") +
                                (layer ? " nor a horizontal slice within the layer" : "") +
                                ": it has no data (not clear air: studies flag lines through it)" +
                                (layer ? "" : "; -l z0,z1 fills it from a horizontal 2D slice, where the case has one"));
    if (source_.empty()) source_ = "2D slices as a layer";
    if (units_ == "C") units_ = "K", offset_ = 273.15;
    times_ = meshes_.front().times;
    if (times_.empty()) throw Error(smv.path + ": the files of '" + quantity + "' hold no frames");
}

void FdsQuantity::setLattice(const SmvIndex& smv, const std::vector<int>& meshes, bool cells) {
    spacing_ = glm::dvec3(std::numeric_limits<double>::infinity());
    for (int m : meshes) spacing_ = glm::min(spacing_, uniformSpacing(smv, m));
    const FdsMesh& first = smv.meshes[size_t(meshes.front())];
    origin_ = glm::dvec3(first.nodes[0][0], first.nodes[1][0], first.nodes[2][0]) + (cells ? 0.5 : 0.0) * spacing_;
}

glm::ivec3 FdsQuantity::refinement(const SmvIndex& smv, int mesh, bool cells) const {
    glm::dvec3 ratio = uniformSpacing(smv, mesh) / spacing_;
    glm::ivec3 r(glm::round(ratio));
    for (int a = 0; a < 3; ++a)
        if (std::abs(ratio[a] - r[a]) > 1e-3 * ratio[a] || (!cells && r[a] != 1))
            throw Error(smv.path + ": mesh " + std::to_string(mesh + 1) + " has cells of " +
                        std::to_string(ratio[a] * spacing_[a]) + " m beside cells of " + std::to_string(spacing_[a]) +
                        " m: " +
                        (cells ? "meshes are imported when their cells are whole multiples of the finest"
                               : "meshes of different resolutions are imported from cell-centred slices only"));
    return r;
}

glm::ivec3 FdsQuantity::place(const SmvIndex& smv, int mesh, const glm::dvec3& p) const {
    glm::dvec3 index = (p - origin_) / spacing_;
    glm::dvec3 rounded = glm::round(index);
    for (int a = 0; a < 3; ++a)
        if (std::abs(index[a] - rounded[a]) > 1e-3 || std::abs(rounded[a]) > 1e8)
            throw Error(smv.path + ": mesh " + std::to_string(mesh + 1) + " is not on the lattice of the finest mesh's cells");
    return glm::ivec3(rounded);
}

// A cell-centred slice's first index along each axis is a ghost cell outside the range (FDS's dump.f90): the
// cells are those after it, cell i centred between nodes i − 1 and i.
void FdsQuantity::addSlice(const SmvIndex& smv, const FdsFile& f, const std::vector<double>& instants) {
    SliceFile s = readSlice(f.path, framesAround(instants, f.path, [&](const Wanted& w) { readSlice(f.path, w); }));
    if (s.range != f.range) throw Error(f.path + ": its index range is not the one " + smv.path + " lists");
    if (s.truncated) warnTruncated(f.path);
    const FdsMesh& m = smv.meshes[size_t(f.mesh)];
    glm::ivec3 lo(f.range[0], f.range[2], f.range[4]), all(f.range[1] - f.range[0] + 1, f.range[3] - f.range[2] + 1,
                                                             f.range[5] - f.range[4] + 1);
    MeshFrames frames;
    frames.size = all - 1;
    frames.refine = refinement(smv, f.mesh, true);
    // The centre of the first lattice voxel inside the first cell: a coarser mesh's cells fill several.
    glm::dvec3 corner(m.nodes[0][size_t(lo[0])], m.nodes[1][size_t(lo[1])], m.nodes[2][size_t(lo[2])]);
    frames.first = place(smv, f.mesh, corner + 0.5 * spacing_);
    for (SliceFrame& frame : s.frames) {
        frames.times.push_back(frame.time);
        std::vector<float> cells;
        cells.reserve(size_t(frames.size.x) * size_t(frames.size.y) * size_t(frames.size.z));
        for (int k = 1; k < all.z; ++k)
            for (int j = 1; j < all.y; ++j)
                for (int i = 1; i < all.x; ++i) cells.push_back(frame.values[size_t(i + all.x * (j + all.y * k))]);
        frames.values.push_back(std::move(cells));
    }
    meshes_.push_back(std::move(frames));
}

void FdsQuantity::warnTruncated(const std::string& path) {
    warnings_.push_back(path + ": ends inside a frame (FDS still running?): its last frame is left out");
}

FdsQuantity::MeshFrames FdsQuantity::nodeFrames(const SmvIndex& smv, int mesh) const {
    const FdsMesh& m = smv.meshes[size_t(mesh)];
    MeshFrames frames;
    frames.size = m.cells + 1;
    frames.refine = refinement(smv, mesh, false);
    frames.first = place(smv, mesh, glm::dvec3(m.nodes[0][0], m.nodes[1][0], m.nodes[2][0]));
    return frames;
}

void FdsQuantity::addSmoke3d(const SmvIndex& smv, const FdsFile& f, const std::vector<double>& instants) {
    const FdsMesh& m = smv.meshes[size_t(f.mesh)];
    if (const std::string path = smoke3d16Beside(f.path); !path.empty()) {
        Smoke3d16File s = readSmoke3d16(
            path, m.cells, framesAround(instants, path, [&](const Wanted& w) { readSmoke3d16(path, m.cells, w); }));
        if (s.truncated) warnTruncated(path);
        MeshFrames frames = nodeFrames(smv, f.mesh);
        for (Smoke3d16Frame& frame : s.frames) {
            frames.times.push_back(frame.time);
            frames.values.push_back(std::move(frame.values));
        }
        meshes_.push_back(std::move(frames));
        return;
    }
    Smoke3dFile s =
        readSmoke3d(f.path, m.cells, framesAround(instants, f.path, [&](const Wanted& w) { readSmoke3d(f.path, m.cells, w); }));
    if (s.truncated) warnTruncated(f.path);
    double km = f.massExtinction;
    if (!(km > 0)) {
        km = kSootMassExtinction;
        warnings_.push_back(f.path + ": no mass extinction coefficient in " + smv.path + ": FDS's default 8700 m2/kg");
    }
    const double dx = m.nodes[0][1] - m.nodes[0][0];  // FDS encodes every node with its mesh's first cell width
    MeshFrames frames = nodeFrames(smv, f.mesh);
    float density[256];
    for (int b = 0; b < 256; ++b) density[b] = float(sootDensity(b, km, dx));
    for (Smoke3dFrame& frame : s.frames) {
        frames.times.push_back(frame.time);
        std::vector<float> nodes(frame.bytes.size());
        for (size_t i = 0; i < nodes.size(); ++i) nodes[i] = density[frame.bytes[i]];
        frames.values.push_back(std::move(nodes));
    }
    meshes_.push_back(std::move(frames));
}

std::string FdsQuantity::addLayer(const SmvIndex& smv, const FdsFile& f, const SliceLayer& layer, double scale,
                                  const std::vector<double>& instants) {
    SliceFile s = readSlice(f.path, framesAround(instants, f.path, [&](const Wanted& w) { readSlice(f.path, w); }));
    if (s.range != f.range) throw Error(f.path + ": its index range is not the one " + smv.path + " lists");
    if (s.truncated) warnTruncated(f.path);
    const FdsMesh& m = smv.meshes[size_t(f.mesh)];
    const glm::ivec3 all(f.range[1] - f.range[0] + 1, f.range[3] - f.range[2] + 1, 1);
    // The lattice's voxels whose centres lie in the mesh's box, between the layer's heights.
    glm::dvec3 lo(m.nodes[0].front(), m.nodes[1].front(), std::max(m.nodes[2].front(), layer.lo));
    glm::dvec3 hi(m.nodes[0].back(), m.nodes[1].back(), std::min(m.nodes[2].back(), layer.hi));
    glm::ivec3 first(glm::ceil((lo - origin_) / spacing_ - 1e-6)), last(glm::floor((hi - origin_) / spacing_ + 1e-6));
    MeshFrames frames;
    frames.first = first;
    frames.size = glm::max(last - first + 1, glm::ivec3(0));
    // Each voxel's slice value: bilinear in plan between the slice's values (at its cells' centres, or its
    // nodes), as a 3D slice's between voxel centres; constant beyond the outermost. A cell-centred slice's first
    // value along x and y is a ghost cell outside the range (addSlice).
    struct Bilinear {
        size_t at[4];
        float w[4];
    };
    std::vector<Bilinear> plan;
    for (int j = 0; j < frames.size.y; ++j)
        for (int i = 0; i < frames.size.x; ++i) {
            int below[2];
            double frac[2];
            for (int a = 0; a < 2; ++a) {
                const std::vector<double>& n = m.nodes[a];
                const double x = origin_[a] + (a == 0 ? first.x + i : first.y + j) * spacing_[a];
                const double d = (n.back() - n.front()) / double(n.size() - 1);
                const int r0 = f.range[2 * a], count = f.range[2 * a + 1] - r0 + (f.cellCentred ? 0 : 1);
                const double u = std::clamp((x - n.front()) / d - r0 - (f.cellCentred ? 0.5 : 0.0), 0.0, double(count - 1));
                below[a] = std::min(int(u), std::max(0, count - 2));
                frac[a] = u - below[a];
                if (f.cellCentred) ++below[a];  // past the ghost
            }
            auto index = [&](int di, int dj) { return size_t(below[0] + di + all.x * (below[1] + dj)); };
            const int nextX = all.x > (f.cellCentred ? 2 : 1), nextY = all.y > (f.cellCentred ? 2 : 1);
            plan.push_back({{index(0, 0), index(nextX, 0), index(0, nextY), index(nextX, nextY)},
                            {float((1 - frac[0]) * (1 - frac[1])), float(frac[0] * (1 - frac[1])),
                             float((1 - frac[0]) * frac[1]), float(frac[0] * frac[1])}});
        }
    for (SliceFrame& frame : s.frames) {
        frames.times.push_back(frame.time);
        std::vector<float> voxels;
        voxels.reserve(plan.size() * size_t(frames.size.z));
        std::vector<float> layerValues;
        for (const Bilinear& b : plan) {
            double v = 0;
            for (int c = 0; c < 4; ++c) v += b.w[c] * frame.values[b.at[c]];
            layerValues.push_back(float(scale * v));
        }
        for (int k = 0; k < frames.size.z; ++k) voxels.insert(voxels.end(), layerValues.begin(), layerValues.end());
        frames.values.push_back(std::move(voxels));
    }
    meshes_.push_back(std::move(frames));
    return "the 2D slice '" + f.quantity + "' at z = " + metres(planeHeight(smv, f)) + " over z " + metres(lo.z) +
           " to " + metres(hi.z);
}

// Every Plot3D file of `first`'s mesh and quantity is a frame (around the instants asked for, if any).
void FdsQuantity::addPlot3d(const SmvIndex& smv, const FdsFile& first, double scale, const std::vector<double>& instants) {
    std::vector<const FdsFile*> files;
    for (const FdsFile& f : smv.files)
        if (f.kind == FdsFile::Kind::Plot3d && f.mesh == first.mesh && f.quantity == first.quantity && fileExists(f.path))
            files.push_back(&f);
    std::sort(files.begin(), files.end(), [](const FdsFile* a, const FdsFile* b) { return a->time < b->time; });
    const Wanted keep = framesAround(instants, first.path, [&](const Wanted& w) {
        for (const FdsFile* f : files) w(f->time);
    });
    const FdsMesh& m = smv.meshes[size_t(first.mesh)];
    MeshFrames frames = nodeFrames(smv, first.mesh);
    for (const FdsFile* f : files) {
        if (keep && !keep(f->time)) continue;
        if (!frames.times.empty() && f->time <= frames.times.back())
            throw Error(f->path + ": two Plot3D files of mesh " + std::to_string(f->mesh + 1) + " at " + seconds(f->time));
        std::vector<float> values = readPlot3dBlock(f->path, m.cells, f->block);
        for (float& v : values) v = float(scale * v);
        frames.times.push_back(f->time);
        frames.values.push_back(std::move(values));
    }
    if (units_.empty()) units_ = scale == 1 ? first.units : "kg/m3";
    meshes_.push_back(std::move(frames));
}

LatticeVoxels FdsQuantity::at(double time) const {
    glm::ivec3 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
    for (const MeshFrames& m : meshes_) lo = glm::min(lo, m.first), hi = glm::max(hi, m.first + m.size * m.refine);
    glm::ivec3 size = hi - lo;
    // Sums and counts: meshes share the nodes on their common faces (3D smoke files), where both give a value.
    std::vector<float> sum(size_t(size.x) * size_t(size.y) * size_t(size.z));
    std::vector<std::uint8_t> count(sum.size());
    for (const MeshFrames& m : meshes_) {
        if (m.times.empty() || time < m.times.front() || time > m.times.back())
            throw Error("no frame at " + std::to_string(time) + " s: the files hold " +
                        (m.times.empty() ? std::string("none") : std::to_string(m.times.front()) + " to " +
                                                                     std::to_string(m.times.back()) + " s"));
        size_t later = size_t(std::upper_bound(m.times.begin(), m.times.end(), time) - m.times.begin());
        size_t before = later == 0 ? 0 : later - 1;
        later = std::min(later, m.times.size() - 1);
        float w = later == before ? 0.f : float((time - m.times[before]) / (m.times[later] - m.times[before]));
        const std::vector<float>&a = m.values[before], &b = m.values[later];
        size_t n = 0;
        for (int k = 0; k < m.size.z; ++k)
            for (int j = 0; j < m.size.y; ++j)
                for (int i = 0; i < m.size.x; ++i, ++n) {
                    const float value = (1 - w) * a[n] + w * b[n];
                    const glm::ivec3 cell = m.first + glm::ivec3(i, j, k) * m.refine - lo;
                    for (int dz = 0; dz < m.refine.z; ++dz)  // a coarser mesh's cell fills several voxels
                        for (int dy = 0; dy < m.refine.y; ++dy)
                            for (int dx = 0; dx < m.refine.x; ++dx) {
                                glm::ivec3 v = cell + glm::ivec3(dx, dy, dz);
                                size_t at = size_t(v.x) + size_t(size.x) * (size_t(v.y) + size_t(size.y) * size_t(v.z));
                                sum[at] += value;
                                ++count[at];
                            }
                }
    }
    LatticeVoxels out;
    out.origin = origin_;
    out.spacing = spacing_;
    size_t n = 0;
    for (int k = 0; k < size.z; ++k)
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i, ++n)
                if (count[n] > 0) {
                    float v = sum[n] / float(count[n]) + float(offset_);
                    if (v != 0) out.values.push_back({lo + glm::ivec3(i, j, k), v});
                }
    return out;
}

}  // namespace brume
