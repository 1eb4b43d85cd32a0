// A sign as a visibility study sees it: a flat polygon of the scene, read from the side its normal faces
// (Radiance's vertex order), of a kind that sets Jin's constant, and the points that sight rays aim at on it
// and on the band of wall around it, its background.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/shapes.h"
#include "scene/scene.h"

namespace brume {

enum class SignKind { Emitting, Reflecting };

struct Sign {
    std::string name;
    SignKind kind = SignKind::Emitting;
    double jinConstant = 8;  // C of Jin's S = C/K: 8 for signs that emit, 3 for those that reflect
    int object = -1;         // its polygon in the scene
    Polygon shape;
    dvec3 centre{0};         // the centroid of its area
    double height = 0;       // its extent up its plane (along +z projected on it; +y for a sign lying flat)
};

// Whether `eye` is on the sign's front side (its polygon's vertex order), where it can be seen from.
bool facing(const Sign& sign, const dvec3& eye);
// "emitting" or "reflecting", as sign lists and reports write the kind.
const char* signKindName(SignKind kind);
// Jin's constant for signs of a kind (Jin 1978; CIBSE Guide E): 8 light-emitting, 3 light-reflecting.
double jinConstant(SignKind kind);
// The distance factor Z of a sign's legibility, d = Z × its height (EN 1838, ISO 3864-1): 200 for signs lit from
// within (emitting), 100 for signs lit from outside (reflecting).
double legibilityFactor(SignKind kind);

// The polygon named `name` in `scene` as a sign. Throws Error where no polygon has that name, or several do,
// or it has no area.
Sign signFromScene(const Scene& scene, const std::string& name, SignKind kind, double jinConstant);

// `n` points spread evenly over the sign's area (a rank-1 lattice folded onto its triangles by area,
// PolygonPoints, the triangle picked by the lattice's irrational coordinate: never a corner, even for n = 1): the
// same points for every observer, a quadrature of the sign's luminance.
std::vector<dvec3> pointsOnSign(const Sign& sign, int n);
// About `n` points spread evenly over the band around the sign: its polygon grown by `grow` about its centre,
// the sign itself left out.
std::vector<dvec3> pointsAroundSign(const Sign& sign, int n, double grow = 1.5);

// Whether p (on the polygon's plane) lies inside it.
bool insidePolygon(const Polygon& polygon, const dvec3& p);

}  // namespace brume
