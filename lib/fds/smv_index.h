// An FDS case's index, the .smv file Smokeview opens: its meshes (cells and node coordinates) and the output
// files written for them (3D smoke, slices, Plot3D: one entry per quantity of a Plot3D file), each with its
// quantity. Only what importing smoke needs is
// read; every other entry (obstructions, vents, boundary and Plot3D files, …) is skipped.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

struct FdsMesh {
    std::string id;
    glm::ivec3 cells{0};                        // IBAR, JBAR, KBAR
    std::array<std::vector<double>, 3> nodes;   // x_0 … x_IBAR, y_…, z_… (metres, OFFSET added)
};

struct FdsFile {
    enum class Kind { Smoke3d, Slice, Plot3d };
    Kind kind = Kind::Slice;
    int mesh = 0;            // index into SmvIndex::meshes
    std::string path;        // as found beside the .smv
    std::string quantity;    // the long label: "SOOT DENSITY", "SOOT EXTINCTION COEFFICIENT", "TEMPERATURE", …
    std::string units;       // "kg/m3", "1/m", "C", …
    int line = 0;            // of its entry in the .smv
    // Smoke3d: the mass extinction coefficient (m²/kg) its bytes were encoded with; 0 for other quantities.
    double massExtinction = 0;
    // Slice: the mesh-local index range i1 i2 j1 j2 k1 k2, and whether values are cell-centred (SLCC).
    std::array<int, 6> range{};
    bool cellCentred = false;
    // Plot3d: which of the file's five blocks holds the quantity, and its instant (from the file's name).
    int block = 0;
    double time = 0;
    // Slice over a volume (three index ranges of more than one), not a plane.
    bool volume() const { return range[1] > range[0] && range[3] > range[2] && range[5] > range[4]; }
};

struct SmvIndex {
    std::string path;
    std::string chid;
    std::vector<FdsMesh> meshes;
    std::vector<FdsFile> files;
};

// Reads the .smv file `path`; file paths are resolved beside it. Throws Error "path:line: what" where an entry
// it reads is malformed, or the meshes do not add up.
SmvIndex readSmv(const std::string& path);

}  // namespace brume
