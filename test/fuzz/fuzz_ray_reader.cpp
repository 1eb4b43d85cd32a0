// libFuzzer target for rtrace's ray input in its three formats, each ray read traced (see README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_rays.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!brume::exerciseRays(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
