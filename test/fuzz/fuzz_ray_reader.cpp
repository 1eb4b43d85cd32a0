// libFuzzer target for rtrace's ray input in its three formats (the first byte picks a, f or d).
#include <cstddef>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>

#include "io/ray_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const char format = "afd"[data[0] % 3];
    std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    brume::RayReader reader(in, format, "(stdin)");
    std::array<double, 6> ray;
    try {
        while (reader.next(ray)) {
        }
    } catch (const brume::Error&) {
    }
    return 0;
}
