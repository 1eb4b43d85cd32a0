// libFuzzer target for weather tapes and Radiance matrices (see README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_daylight.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    brume::setWarningsEnabled(false);
    if (!brume::exerciseDaylightInput(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
