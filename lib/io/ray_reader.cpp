#include "io/ray_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace brume {

// One whitespace-separated word as a number, read straight from the stream buffer (rays come by the
// million; formatted extraction costs more than tracing them).
bool RayReader::word(double& v) {
    std::streambuf* buf = in_.rdbuf();
    int c = buf->sgetc();
    while (c != EOF && std::isspace(c)) c = buf->snextc();
    char w[64];
    size_t n = 0;
    while (c != EOF && !std::isspace(c)) {
        if (n + 1 < sizeof w) w[n++] = char(c);
        else return false;  // no number is that long
        c = buf->snextc();
    }
    if (n == 0) return false;
    w[n] = '\0';
    char* end = nullptr;
    v = std::strtod(w, &end);
    return end == w + n && std::isfinite(v);
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
