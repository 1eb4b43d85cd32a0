// libFuzzer target for the Wavefront .obj reader (see README.md): every input is read or refused with a
// message, and what is read is a mesh whose indices all point into it. Material names of one or two letters
// stand for object 0; longer ones are undefined.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "mesh_invariants.h"
#include "scene/mesh.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool quiet = (brume::setWarningsEnabled(false), true);  // "statements unrecognized" noise
    (void)quiet;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        brume::Mesh mesh =
            brume::readWavefront(in, "fuzz.obj", [](const std::string& n) { return n.size() < 3 ? 0 : -1; });
        brume::fuzz::checkMesh(mesh, 1);
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
