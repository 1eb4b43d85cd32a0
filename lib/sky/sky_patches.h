// The sky's patches as Radiance's daylight matrices number them (gendaymtx, reinhart.cal): patch 0 the
// ground, then Tregenza's 145 patches (-m 1) or Reinhart's subdivisions of them (-m N: each of the seven
// rows cut into N rows and each patch into N across, N² × 144 + 1 patches), rows from the horizon up, each row
// starting at north and going east, the zenith cap last.
#pragma once
#include <glm/vec3.hpp>
#include <vector>

namespace brume {

struct SkyPatch {
    // Radiance keeps these in single precision; its values follow from that.
    float altitude;    // of the patch's centre, radians (the ground: -π/2)
    float azimuth;     // radians east of north
    float solidAngle;  // sr (the ground: 2π)
};

class SkyPatches {
public:
    explicit SkyPatches(int subdivisions);
    int subdivisions() const { return subdivisions_; }
    int size() const { return int(patches_.size()); }
    const SkyPatch& operator[](int i) const { return patches_[i]; }
    // The unit vector toward a patch's centre (x east, y north, z up).
    glm::dvec3 direction(int i) const;
    // The patch a unit direction falls in (0: below the horizon), as reinhart.cal's rbin bins it.
    int patchAt(const glm::dvec3& direction) const;

private:
    int subdivisions_;
    std::vector<int> rowStarts_;  // the first patch of each row, and one past the last
    std::vector<SkyPatch> patches_;
};

// Radiance's tabulated sine (its tsin in builds without -ffast-math): the sine at the nearest multiple of
// π/2048. gendaymtx weighs patches by it when it normalises the sky to its diffuse illuminance.
double tabulatedSine(double x);

}  // namespace brume
