// FDS's 16-bit 3D smoke files (.s16, &MISC SMOKE3D_16=T, FDS >= 6.8), written beside each .s3d under the same
// name and not listed in the .smv: per output instant, the quantity itself (soot density in kg/m³, HRRPUV,
// temperature in °C) at every node of a mesh, the plain mean of the 8 cells around it, as 16-bit steps between
// the frame's own least and largest values. FDS truncates to the step below, so a value reads up to one step
// ((max − min)/65535) low.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

struct Smoke3d16Frame {
    double time;                // seconds
    std::vector<float> values;  // (IBAR+1)(JBAR+1)(KBAR+1) nodes, i fastest, then j, then k
};

struct Smoke3d16File {
    std::vector<Smoke3d16Frame> frames;  // in time order
    bool truncated = false;              // the file ended inside a frame (dropped)
};

// The .s16 file beside the 3D smoke file `s3dPath` ("" where there is none).
std::string smoke3d16Beside(const std::string& s3dPath);

// The frames of `path`, a mesh of `cells` cells, those at times `wanted` says (all by default). Throws Error
// "path: …" where the file is not a 16-bit smoke file of that mesh (its header: 1, version 1, uncompressed, the
// node counts), a frame's counts or sizes are not one value per node, its range is not finite, or times do not
// increase.
Smoke3d16File readSmoke3d16(const std::string& path, const glm::ivec3& cells,
                            const std::function<bool(double)>& wanted = nullptr);

}  // namespace brume
