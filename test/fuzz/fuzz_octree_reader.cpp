// libFuzzer target for the octree reader (see README.md). Scene files a mutated normal octree lists are
// read from the current directory; "!command" names are refused, never run.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "scene/octree.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool quiet = (brume::setWarningsEnabled(false), true);  // "empty scene file" noise
    (void)quiet;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    brume::Scene scene;
    try {
        brume::readOctree(scene, in, "fuzz.oct", {.allowCommands = false});
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
