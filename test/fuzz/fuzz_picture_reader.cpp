// libFuzzer target for the Radiance picture readers (RGBE/XYZE, every encoding and scan order, and hyperspectral pictures), as colorpict and specpict read them (see README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_pattern_data.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!brume::exercisePicture(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
