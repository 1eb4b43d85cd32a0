// The surfaces of an rfluxmtx sender or receiver file: polygons, rings and sources (other objects are
// skipped), each with its real arguments, area and normal, and the "#@rfluxmtx" settings lines read since the
// surface before it (h= hemisphere basis, u= up, o= output), which receivers and senders apply each in their own
// way.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "util/error.h"

namespace brume {

// Reinhart's subdivisions an h= may ask for: 100 makes 1.44 million patches.
constexpr int kMaxSubdivisions = 100;

struct FluxSettings {
    char sign = '+';         // h=-…: a left-handed frame
    std::string hemisphere;  // h= without its sign: "u", "r4", "kf", …
    int size = 1;            // the number in h= (Reinhart's MF), 1 if none
    std::optional<glm::dvec3> up;  // u=
    std::string output;            // o=
};

// Which Klems basis an h= names: 'f' (kf, k, k1: Full), 'h' (kh, k2: Half), 'q' (kq, k4: Quarter), or 0, as
// Radiance's rfluxmtx reads them (the letter after the k decides).
char klemsBasisOf(const std::string& hemisphere);

// The up direction of a hemisphere about unit `normal`: u=, else z, or y where the normal is within 45.6° of z.
glm::dvec3 upOf(const FluxSettings& s, const glm::dvec3& normal);

// Applies the words of a "#@rfluxmtx" line (after its marker) to `s`. Throws Error (at `where`) for a word
// that is not h=, u= or o=, or a bad one.
void applyFluxSettings(const std::string& words, FluxSettings& s, const SourceLocation& where);

struct FluxSurface {
    std::string modifier, type, name;
    SourceLocation at;
    std::vector<double> arguments;  // its reals
    double area;                    // a source's: the solid angle of its cone
    glm::dvec3 normal;              // unit: a polygon's by its vertices' right-hand order, a ring's, a source's
                                    // opposite its direction
    bool source;
    std::vector<std::pair<SourceLocation, std::string>> settings;  // "#@rfluxmtx" lines before it
};

// The file's surfaces in order, those of no area left out with a warning. Throws Error (file:line) for a file
// that cannot be read, commands, bad arguments.
std::vector<FluxSurface> readFluxSurfaces(const std::string& path, const std::string& role);

}  // namespace brume
