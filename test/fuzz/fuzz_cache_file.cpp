// libFuzzer target for irradiance cache files (-af; see README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_cache_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!brume::exerciseCacheFile(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
