// libFuzzer target for view lines (view files, rpict -S input) and camera paths (see README.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_view.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (!brume::exerciseViewText(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
