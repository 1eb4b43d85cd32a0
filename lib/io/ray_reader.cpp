#include "io/ray_reader.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace brume {

bool RayReader::word(double& v) {
    std::string w;
    if (!(in_ >> w)) return false;
    char* end = nullptr;
    v = std::strtod(w.c_str(), &end);
    return end && *end == '\0' && end != w.c_str() && std::isfinite(v);
}

bool RayReader::next(std::array<double, 6>& ray) {
    for (int i = 0; i < 6; ++i) {
        bool ok;
        if (format_ == 'f') {
            float f;
            ok = static_cast<bool>(in_.read(reinterpret_cast<char*>(&f), sizeof f)) && std::isfinite(f);
            ray[i] = f;
        } else if (format_ == 'd') {
            ok = static_cast<bool>(in_.read(reinterpret_cast<char*>(&ray[i]), sizeof(double))) &&
                 std::isfinite(ray[i]);
        } else {
            ok = word(ray[i]);
        }
        if (!ok) {
            partial_ = i > 0;
            return false;
        }
    }
    return true;
}

}  // namespace brume
