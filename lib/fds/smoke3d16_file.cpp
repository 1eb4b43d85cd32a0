#include "fds/smoke3d16_file.h"

#include <cmath>
#include <filesystem>

#include "fds/fortran_records.h"
#include "util/error.h"

namespace brume {

std::string smoke3d16Beside(const std::string& s3dPath) {
    const std::string suffix = ".s3d";
    if (s3dPath.size() < suffix.size() || s3dPath.compare(s3dPath.size() - suffix.size(), suffix.size(), suffix) != 0)
        return "";
    std::string path = s3dPath.substr(0, s3dPath.size() - suffix.size()) + ".s16";
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec) ? path : "";
}

Smoke3d16File readSmoke3d16(const std::string& path, const glm::ivec3& cells, const std::function<bool(double)>& wanted) {
    FortranRecords records(path);
    std::vector<char> r;
    records.expect(r, 24, "the header");
    const int expected[6] = {1, 1, 0, cells.x + 1, cells.y + 1, cells.z + 1};
    for (int i = 0; i < 6; ++i)
        if (int32At(r, size_t(i)) != expected[i])
            throw Error(path + ": header (" + std::to_string(int32At(r, 0)) + ", " + std::to_string(int32At(r, 1)) +
                        ", " + std::to_string(int32At(r, 2)) + " …) is not that of an uncompressed 16-bit smoke file (version 1) of " +
                        std::to_string(cells.x) + " x " + std::to_string(cells.y) + " x " + std::to_string(cells.z) + " cells");
    const size_t nodes = size_t(cells.x + 1) * size_t(cells.y + 1) * size_t(cells.z + 1);
    Smoke3d16File file;
    std::vector<char> data;
    float lo = 0, hi = 0;
    file.truncated = forEachFrame(
        records,
        [&](size_t k, std::uint64_t at) {
            if (records.next(r) != FortranRecords::Next::Record) return false;
            if (r.size() != 16 || size_t(int32At(r, 0)) != nodes || size_t(int32At(r, 1)) != nodes)
                frameError(records, k, at, "expected its counts, one value per node, and its range");
            lo = float32At(r, 2), hi = float32At(r, 3);
            if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi >= lo)) frameError(records, k, at, "its range is not finite");
            if (records.next(data) != FortranRecords::Next::Record) return false;
            if (data.size() != 2 * nodes) frameError(records, k, at, "expected two bytes per node");
            return true;
        },
        wanted,
        [&](size_t, double time, std::uint64_t) {
            Smoke3d16Frame& frame = file.frames.emplace_back(Smoke3d16Frame{time, std::vector<float>(nodes)});
            const double step = (double(hi) - double(lo)) / 65535;
            for (size_t n = 0; n < nodes; ++n) {  // big-endian steps, whatever the machine's order
                const unsigned u = (unsigned(std::uint8_t(data[2 * n])) << 8) | std::uint8_t(data[2 * n + 1]);
                frame.values[n] = float(lo + step * u);
            }
        });
    return file;
}

}  // namespace brume
