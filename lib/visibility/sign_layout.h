// Signs placed by where they are, not by their polygons: a centre, the direction their front faces, a width and
// a height, the kind, and what they show (an emitting sign's luminance, a reflecting one's reflectance), one per
// line of a text file:
//   # name      centre (m)         front      width height  kind        L (cd/m²) or ρ   [Jin's C]
//   north_exit  17.47 9.99 2.35    0 -1 0     0.4   0.2     emitting    150
//   plan        12.5  0.01 1.5     0  1 0     0.4   0.3     reflecting  0.8
// so that no one has to get a polygon's vertex order right: the program writing the scene makes the polygon.
#pragma once
#include <array>
#include <istream>
#include <string>
#include <vector>

#include "visibility/sign.h"

namespace brume {

struct SignPlacement {
    std::string name;
    dvec3 centre{0}, front{0};  // front: unit
    double width = 0, height = 0;
    SignKind kind = SignKind::Emitting;
    double shows = 0;  // cd/m² (emitting), reflectance (reflecting)
    double jinConstant = 8;
    std::string where;  // "file:line"

    // Its corners, counter-clockwise seen from the front (Radiance's order): its width horizontal, its height
    // along the wall upward (for a sign facing up or down, along +y).
    std::array<dvec3, 4> corners() const;
};

// Throws Error "file:line: what is wrong": a malformed line, a front of no length, a size or luminance ≤ 0, a
// reflectance outside (0, 1], a name given twice, no signs.
std::vector<SignPlacement> readSignPlacements(std::istream& in, const std::string& file);

}  // namespace brume
