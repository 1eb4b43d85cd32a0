// libFuzzer target for the compiled Radiance mesh reader (see README.md): every input is read or refused with
// a message, and what is read is a mesh whose indices all point into it.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "mesh_invariants.h"
#include "scene/mesh.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    brume::Scene scene;
    try {
        brume::Mesh mesh = brume::readRadianceMesh(scene, in, "fuzz.rtm");
        brume::fuzz::checkMesh(mesh, scene.objects.size());
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
