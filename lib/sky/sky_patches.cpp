#include "sky/sky_patches.h"

#include <algorithm>
#include <cmath>

#include "sky/solar_position.h"

namespace brume {

namespace {
constexpr int kRows = 7;
constexpr int kPatchesInRow[kRows] = {30, 30, 24, 24, 18, 12, 6};
}  // namespace

SkyPatches::SkyPatches(int m) : subdivisions_(m) {
    // Rows of equal altitude span, the zenith cap half a row high.
    const double alpha = (kPi / 2) / (kRows * m + 0.5);
    patches_.push_back({float(-kPi / 2), 0.f, float(2 * kPi)});
    for (int i = 0; i < kRows * m; ++i) {
        rowStarts_.push_back(int(patches_.size()));
        const float altitude = float(alpha * (i + 0.5));
        const int inRow = kPatchesInRow[i / m] * m;
        const float solidAngle = float(2 * kPi * (std::sin(alpha * (i + 1)) - std::sin(alpha * i)) / inRow);
        for (int j = 0; j < inRow; ++j) patches_.push_back({altitude, float(2 * kPi * j / inRow), solidAngle});
    }
    rowStarts_.push_back(int(patches_.size()));
    patches_.push_back({float(kPi / 2), 0.f, float(2 * kPi * (1 - std::cos(alpha * 0.5)))});
    rowStarts_.push_back(int(patches_.size()));
}

int SkyPatches::patchAt(const glm::dvec3& d) const {
    double altitude = std::asin(std::clamp(d.z, -1.0, 1.0)) / kDegree;
    if (altitude <= 0) return 0;
    int rows = kRows * subdivisions_;
    int row = std::min(int(altitude / (90 / (rows + 0.5))), rows);
    int count = rowStarts_[row + 1] - rowStarts_[row];
    double azimuth = std::atan2(d.x, d.y) / kDegree;
    if (azimuth < 0) azimuth += 360;
    // Patches centred on their azimuths, the first on north: the last half step wraps to it.
    double step = 360.0 / count;
    int column = azimuth < 359.9999 - step / 2 ? int((azimuth + step / 2) / step) : 0;
    return rowStarts_[row] + column;
}

glm::dvec3 SkyPatches::direction(int i) const {
    double cosAltitude = std::cos(double(patches_[i].altitude));
    return {cosAltitude * std::sin(double(patches_[i].azimuth)), cosAltitude * std::cos(double(patches_[i].azimuth)),
            std::sin(double(patches_[i].altitude))};
}

// tsin(x) = tcos(x - π/2), the cosine read from a table of 1024 entries a quadrant without interpolation.
double tabulatedSine(double x) {
    constexpr int kEntries = 1024;
    double a = std::abs(x - kPi / 2);
    int i = int(kEntries * 2 / kPi * a + 0.5) % (4 * kEntries);
    auto entry = [](int k) { return std::cos(kPi / 2 / kEntries * k); };
    switch (i / kEntries) {
        case 0: return entry(i);
        case 1: return -entry(2 * kEntries - i);
        case 2: return -entry(i - 2 * kEntries);
        default: return entry(4 * kEntries - i);
    }
}

}  // namespace brume
