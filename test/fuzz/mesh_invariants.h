// What any mesh read must satisfy, checked by the mesh fuzzers and the corpus replay test: a failure traps.
#pragma once
#include <cmath>

#include "scene/mesh.h"

namespace brume::fuzz {

inline void checkMesh(const Mesh& m, size_t objects) {
    auto require = [](bool ok) {
        if (!ok) __builtin_trap();
    };
    require(!m.triangles.empty() && m.materials.size() == m.triangles.size());
    require(m.normals.empty() || m.normals.size() == m.vertices.size());
    require(m.uvs.empty() || m.uvs.size() == m.vertices.size());
    for (const auto& t : m.triangles)
        for (uint32_t v : t) require(v < m.vertices.size());
    for (int material : m.materials) require(material >= -1 && material < int(objects));
    for (const auto& v : m.vertices) require(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

}  // namespace brume::fuzz
