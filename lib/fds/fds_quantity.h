// One quantity of an FDS case (soot density, temperature, …) over all its meshes and output instants, as
// voxels of one lattice: what an OpenVDB grid holds. From the best files the case has for it: cell-centred 3D
// slices (the cells' own values, as FDS computed them), else the 3D smoke files: their 16-bit twins (.s16, any
// quantity, node values within a step of 1/65535 of the frame's range), else for soot density the 8-bit
// opacities (±0.02 /m of extinction at 0.1 m cells, smoke3d_file.h), else Plot3D files (nodes, full floats, at
// their few instants; soot density from soot's extinction over K_m); meshes without any from a horizontal 2D
// slice over a layer of heights, when asked (SliceLayer).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "fds/smv_index.h"

namespace brume {

// Voxel (i, j, k) is centred at origin + (i, j, k) · spacing (world metres); voxels not listed hold 0.
struct LatticeVoxels {
    glm::dvec3 origin{0}, spacing{0};
    std::vector<std::pair<glm::ivec3, float>> values;
};

// Meshes without 3D data filled from a horizontal 2D slice (FDSVisMap's assumption made explicit): the slice's
// values, cell by cell in plan, over heights lo to hi of each such mesh.
struct SliceLayer {
    double lo = 0, hi = 0;  // metres
};

// What a mesh's values came from.
enum class MeshSource { None, Volume, Layer };

class FdsQuantity {
public:
    // The meshes' files of `quantity` (a long label as the .smv has it, e.g. "SOOT DENSITY") in the index `smv`:
    // the frames around each of `instants` (seconds), or all frames if none are given. Temperatures in °C become
    // kelvin. Meshes of coarser cells (whole multiples of the finest, cell-centred slices only) fill several
    // voxels per cell. Throws Error "smv: …" where no file has the quantity (naming those that the case has),
    // meshes are not on one lattice (stretched cells, cells that are not multiples, meshes off the lattice), or
    // "file: …" where a file cannot be read or has no frames around an instant.
    // With `layer`, meshes without 3D data of the quantity take a horizontal 2D slice's over the layer's heights,
    // from a slice of the quantity itself or of soot's extinction or optical density (K = 2.3 × the optical
    // density, as FDS writes it; soot density = K over the mass extinction coefficient); Error where the case has 3D data in no
    // mesh and no such slice either.
    FdsQuantity(const SmvIndex& smv, const std::string& quantity, const std::vector<double>& instants = {},
                const std::optional<SliceLayer>& layer = std::nullopt);

    // The instants of the first mesh's frames that were read (seconds): with instants given, only those around them.
    const std::vector<double>& times() const { return times_; }
    // The voxels at `time`, linear in time between the frames around it; Error if a mesh has no frames around
    // it.
    LatticeVoxels at(double time) const;
    // The units of the values (kg/m3, K, …) and where they came from, for headers and messages.
    const std::string& units() const { return units_; }
    const std::string& source() const { return source_; }
    // Per mesh of the index: where its values came from, and in words (e.g. "3D smoke files (8-bit opacities)",
    // "the 2D slice 'SOOT EXTINCTION COEFFICIENT' at z = 2.05 m over 1.5-2.5 m", "" where none).
    const std::vector<MeshSource>& meshSources() const { return meshSources_; }
    const std::vector<std::string>& meshSourceNotes() const { return meshNotes_; }
    // What the caller should tell the user (meshes without the quantity, a truncated file, …).
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    struct MeshFrames {
        glm::ivec3 first{0}, size{0};           // the lattice index of its first value, and its values per axis
        glm::ivec3 refine{1};                   // the lattice voxels per value along each axis (a coarser mesh's)
        std::vector<double> times;
        std::vector<std::vector<float>> values;  // per frame, over size, x fastest
    };
    using Wanted = std::function<bool(double)>;
    // The frames of a mesh's values at its nodes (3D smoke and Plot3D files), none read yet.
    MeshFrames nodeFrames(const SmvIndex& smv, int mesh) const;
    void warnTruncated(const std::string& path);  // a file FDS is still writing
    void addSlice(const SmvIndex& smv, const FdsFile& f, const std::vector<double>& instants);
    void addSmoke3d(const SmvIndex& smv, const FdsFile& f, const std::vector<double>& instants);
    // The slice `f` (horizontal, of a mesh without 3D data) over the layer's heights of its mesh, its values
    // times `scale`, onto the lattice's voxels whose centres lie in the mesh's box and the layer. Returns what
    // it did, in words.
    // The Plot3D files of `first`'s mesh and quantity, their values times `scale`.
    void addPlot3d(const SmvIndex& smv, const FdsFile& first, double scale, const std::vector<double>& instants);
    std::string addLayer(const SmvIndex& smv, const FdsFile& f, const SliceLayer& layer, double scale,
                         const std::vector<double>& instants);
    // The lattice: the finest cells of `meshes`, aligned with the first one's (its cell centres, or its nodes for
    // 3D smoke files, `cells` false).
    void setLattice(const SmvIndex& smv, const std::vector<int>& meshes, bool cells);
    // How many lattice voxels a mesh's value fills along each axis; Error unless whole numbers (1 for nodes).
    glm::ivec3 refinement(const SmvIndex& smv, int mesh, bool cells) const;
    // The lattice index of world point p, which must be a voxel centre.
    glm::ivec3 place(const SmvIndex& smv, int mesh, const glm::dvec3& p) const;

    std::vector<MeshFrames> meshes_;
    std::vector<double> times_;
    glm::dvec3 origin_{0}, spacing_{0};
    std::string units_, source_;
    double offset_ = 0;  // added to every value: 273.15 for °C
    std::vector<std::string> warnings_;
    std::vector<MeshSource> meshSources_;
    std::vector<std::string> meshNotes_;
};

}  // namespace brume
