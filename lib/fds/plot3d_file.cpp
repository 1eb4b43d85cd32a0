#include "fds/plot3d_file.h"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "fds/fortran_records.h"
#include "util/error.h"

namespace brume {

std::vector<float> readPlot3dBlock(const std::string& path, const glm::ivec3& cells, int block) {
    FortranRecords records(path);
    std::vector<char> r;
    records.expect(r, 12, "the node counts");
    const glm::ivec3 nodes = cells + 1;
    if (int32At(r, 0) != nodes.x || int32At(r, 1) != nodes.y || int32At(r, 2) != nodes.z)
        throw Error(path + ": its node counts (" + std::to_string(int32At(r, 0)) + " x " + std::to_string(int32At(r, 1)) +
                    " x " + std::to_string(int32At(r, 2)) + ") are not those of its mesh (" + std::to_string(nodes.x) +
                    " x " + std::to_string(nodes.y) + " x " + std::to_string(nodes.z) + ")");
    records.expect(r, 16, "the four reals before the data");
    const size_t n = size_t(nodes.x) * size_t(nodes.y) * size_t(nodes.z);
    records.expect(r, 5 * n * 4, "five blocks of one value per node");
    std::vector<float> values(n);
    for (size_t i = 0; i < n; ++i) {
        values[i] = float32At(r, size_t(block) * n + i);
        if (!std::isfinite(values[i])) throw Error(path + ": a value that is not finite in block " + std::to_string(block + 1));
    }
    return values;
}

std::optional<double> plot3dTime(const std::string& path) {
    const std::string stem = std::filesystem::path(path).stem().string();
    const size_t underscore = stem.rfind('_'), p = stem.rfind('p');
    if (underscore == std::string::npos || p == std::string::npos || p < underscore) return std::nullopt;
    const std::string whole = stem.substr(underscore + 1, p - underscore - 1), hundredths = stem.substr(p + 1);
    int w = 0, h = 0;
    auto [a, e1] = std::from_chars(whole.data(), whole.data() + whole.size(), w);
    auto [b, e2] = std::from_chars(hundredths.data(), hundredths.data() + hundredths.size(), h);
    if (e1 != std::errc() || e2 != std::errc() || a != whole.data() + whole.size() ||
        b != hundredths.data() + hundredths.size() || hundredths.size() != 2)
        return std::nullopt;
    return w + h / 100.0;
}

}  // namespace brume
