// libFuzzer target for the .cal language (see README.md and exercise_cal.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "exercise_cal.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool quiet = (brume::setWarningsEnabled(false), true);  // math warnings
    (void)quiet;
    if (!brume::cal::exerciseCal(std::string_view(reinterpret_cast<const char*>(data), size))) __builtin_trap();
    return 0;
}
