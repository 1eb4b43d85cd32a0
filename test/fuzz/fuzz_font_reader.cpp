// libFuzzer target for the font reader (see README.md): every input is read or refused with a message, and
// a font that reads can be written with.
#include <cstddef>
#include <cstdint>
#include <string>

#include "exercise_font.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        brume::fuzz::exerciseFont(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
