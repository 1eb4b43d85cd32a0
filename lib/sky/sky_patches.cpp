#include "sky/sky_patches.h"

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
        const float altitude = float(alpha * (i + 0.5));
        const int inRow = kPatchesInRow[i / m] * m;
        const float solidAngle = float(2 * kPi * (std::sin(alpha * (i + 1)) - std::sin(alpha * i)) / inRow);
        for (int j = 0; j < inRow; ++j) patches_.push_back({altitude, float(2 * kPi * j / inRow), solidAngle});
    }
    patches_.push_back({float(kPi / 2), 0.f, float(2 * kPi * (1 - std::cos(alpha * 0.5)))});
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
