#include "io/ray_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include <glm/geometric.hpp>

#include "util/error.h"

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

InputRay inputRay(const std::array<double, 6>& r) {
    dvec3 org(r[0], r[1], r[2]), dir(r[3], r[4], r[5]);
    // Scaled by its largest component first: the squares of components beyond 1e154 overflow, those of
    // components below 1e-154 vanish.
    double largest = std::max({std::abs(dir.x), std::abs(dir.y), std::abs(dir.z)});
    if (largest == 0) return {org, dir, 0, true};
    dvec3 scaled = dir / largest;
    double length = glm::length(scaled);
    return {org, scaled / length, largest * length, false};
}

bool RayBatches::next(std::vector<InputRay>& rays) {
    first_ = uint64_t(count_);
    rays.clear();
    std::array<double, 6> r;
    while (!done_ && rays.size() < size_) {
        if (limit_ > 0 && count_ >= limit_) {
            done_ = true;
            break;
        }
        if (!reader_.next(r)) {
            done_ = true;
            if (limit_ > 0) warn("unexpected EOF on input");
            break;
        }
        ++count_;
        rays.push_back(inputRay(r));
        if (rays.back().zero) break;  // a flush request: finish what came before it
    }
    return !rays.empty();
}

}  // namespace brume
