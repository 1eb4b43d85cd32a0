// libFuzzer target for the .rad parser (see README.md). "!command" lines are refused, never run.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "scene/reader.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool quiet = (brume::setWarningsEnabled(false), true);  // "empty scene file" noise
    (void)quiet;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    brume::Scene scene;
    try {
        brume::readSceneText(scene, in, "fuzz.rad", {.allowCommands = false});
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
