// FDS's 3D smoke files (.s3d, SMOKF3D in the .smv): per output instant, one byte per node of a mesh,
// run-length encoded. For soot a byte is not a density but the opacity of one cell width, 254·(1 − e^{−K_m ρ Δx})
// rounded (FDS's dump.f90; Smokeview inverts it the same way), ρ the mean soot density of the 8 cells around the
// node and Δx the width of the mesh's first cell along x.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

struct Smoke3dFrame {
    double time;                      // seconds
    std::vector<std::uint8_t> bytes;  // (IBAR+1)(JBAR+1)(KBAR+1) nodes, i fastest, then j, then k; 0 … 254
};

struct Smoke3dFile {
    std::vector<Smoke3dFrame> frames;  // in time order
    bool truncated = false;            // the file ended inside a frame (dropped)
};

// The frames of `path`, a mesh of `cells` cells, those at times `wanted` says (all by default; the others are
// read past, not decoded). Throws Error "path: …" where the file is not one of that
// mesh's 3D smoke files, a frame does not decode to one byte per node, or times do not increase.
Smoke3dFile readSmoke3d(const std::string& path, const glm::ivec3& cells,
                        const std::function<bool(double)>& wanted = nullptr);

// Soot density (kg/m³) from a soot byte, encoded with mass extinction `massExtinction` (m²/kg) over a cell
// width `dx` (m). A byte b stands for the densities of b ± 0.5 (so the ends of that interval come from
// fractional bytes); 254, opaque over a cell, for those of at least 253.5, and gives that.
double sootDensity(double byte, double massExtinction, double dx);

}  // namespace brume
