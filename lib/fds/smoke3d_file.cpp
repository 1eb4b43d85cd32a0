#include "fds/smoke3d_file.h"

#include <cmath>

#include "fds/fortran_records.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr std::uint8_t kEscape = 255;  // 255, v, n: n copies of v

// Smokeview's run-length code into exactly `out.size()` bytes; false if it does not fill them exactly.
bool decode(const std::vector<char>& in, std::vector<std::uint8_t>& out) {
    size_t o = 0;
    for (size_t i = 0; i < in.size();) {
        auto b = std::uint8_t(in[i]);
        if (b != kEscape) {
            if (o == out.size()) return false;
            out[o++] = b;
            ++i;
            continue;
        }
        if (i + 2 >= in.size()) return false;
        auto value = std::uint8_t(in[i + 1]);
        size_t n = std::uint8_t(in[i + 2]);
        if (value == kEscape || n > out.size() - o) return false;
        std::fill_n(out.begin() + std::ptrdiff_t(o), n, value);
        o += n;
        i += 3;
    }
    return o == out.size();
}

}  // namespace

Smoke3dFile readSmoke3d(const std::string& path, const glm::ivec3& cells, const std::function<bool(double)>& wanted) {
    FortranRecords records(path);
    std::vector<char> r;
    records.expect(r, 32, "the header");
    const int expected[8] = {1, 0, 0, cells.x, 0, cells.y, 0, cells.z};
    for (int i = 0; i < 8; ++i)
        if (int32At(r, size_t(i)) != expected[i])
            throw Error(path + ": header (" + std::to_string(int32At(r, 0)) + " …) is not that of a 3D smoke file of " +
                        std::to_string(cells.x) + " x " + std::to_string(cells.y) + " x " + std::to_string(cells.z) +
                        " cells");
    const size_t nodes = size_t(cells.x + 1) * size_t(cells.y + 1) * size_t(cells.z + 1);
    Smoke3dFile file;
    std::vector<char> data;
    file.truncated = forEachFrame(
        records,
        [&](size_t k, std::uint64_t at) {
            if (records.next(r) != FortranRecords::Next::Record) return false;
            if (r.size() != 8 || size_t(int32At(r, 0)) != nodes) frameError(records, k, at, "expected its sizes, one byte per node");
            if (records.next(data) != FortranRecords::Next::Record) return false;
            if (data.size() != size_t(int32At(r, 1))) frameError(records, k, at, "compressed data of the wrong size");
            return true;
        },
        wanted,
        [&](size_t k, double time, std::uint64_t at) {
            Smoke3dFrame& frame = file.frames.emplace_back(Smoke3dFrame{time, std::vector<std::uint8_t>(nodes)});
            if (!decode(data, frame.bytes)) frameError(records, k, at, "its run-length code does not give one byte per node");
        });
    return file;
}

// FDS's encoding, b = 254 (1 − exp(−K_m ρ Δx)), inverted (Smokeview's too).
double sootDensity(double byte, double massExtinction, double dx) {
    return -std::log1p(-std::min(byte, 253.5) / 254.0) / (massExtinction * dx);
}

}  // namespace brume
