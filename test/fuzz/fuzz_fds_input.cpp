// libFuzzer target for FDS input files and sign placements (fds2rad's inputs; see README.md): the first byte picks
// which ('s' a sign list, anything else an .fds file); every input is read or refused with a message, and what is
// read gives finite geometry (exercise_fds_input.h).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "exercise_fds_input.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    try {
        if (data[0] == 's') brume::fuzz::exerciseSignPlacements(in);
        else brume::fuzz::exerciseFdsInput(in);
    } catch (const brume::Error&) {
        // Rejecting bad input with a message is the expected outcome.
    }
    return 0;
}
