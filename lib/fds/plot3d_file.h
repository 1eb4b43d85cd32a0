// FDS's Plot3D files (.q, PL3D in the .smv): at one instant, five quantities of a mesh at its nodes (those
// DUMP PLOT3D_QUANTITY names, the .smv listing their labels), each node the mean of the gas cells around it. The
// file holds no time: FDS writes it into the name (CHID_mesh_5p03.q for 5.03 s), and the .smv's copy drops the
// zero of the hundredths (5.3).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

// Block `block` (0-4) of the Plot3D file `path` of a mesh of `cells` cells: (IBAR+1)(JBAR+1)(KBAR+1) node values,
// i fastest, then j, then k. Throws Error "path: …" where the file is not a Plot3D file of that mesh (its node
// counts, its five blocks) or a value is not finite.
std::vector<float> readPlot3dBlock(const std::string& path, const glm::ivec3& cells, int block);

// The instant in a Plot3D file's name ("…_5p03.q": 5.03 s), or none.
std::optional<double> plot3dTime(const std::string& path);

}  // namespace brume
