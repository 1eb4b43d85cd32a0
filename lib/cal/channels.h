// The ray values a .cal expression reads as $N: the renderer fills `Channels` per ray and pattern, in the
// pattern's own coordinates (after its transform), and the standard library names them (Dx = $1, ...).
#pragma once
#include <array>

namespace brume::cal {

// Channels 1-27 are Radiance's (rt/func.c and rayinit.cal); a .cal file written for Radiance reads the
// same value from the same $N. Channels 28 and up are Brume's: Radiance sets these names as variables
// for *func/*data materials and prisms, Brume passes them like the others.
// clang-format off
enum Channel : int {
    Dx = 1, Dy, Dz,     // ray direction
    Nx, Ny, Nz,         // surface normal
    Px, Py, Pz,         // intersection point
    T,                  // distance from the ray's start
    Rdot,               // -D.N: cosine of the angle of incidence, positive on the front, in [-1, 1]
    S,                  // world scale
    Tx, Ty, Tz,         // world origin
    Ix, Iy, Iz,         // world i unit vector
    Jx, Jy, Jz,         // world j unit vector
    Kx, Ky, Kz,         // world k unit vector
    Ts,                 // single (shadow) ray distance
    Lu, Lv,             // mesh local (u, v) coordinates
    NxP, NyP, NzP,      // perturbed normal (*func and *data materials)
    RdotP,              // perturbed ray dot product
    CrP, CgP, CbP,      // perturbed material colour
    DxA, DyA, DzA,      // direction to the target light source (prism materials)
};
// clang-format on

// Index 0 is unused so that channels[Dx] is $1.
constexpr int kChannelCount = DzA + 1;
using Channels = std::array<double, kChannelCount>;

}  // namespace brume::cal
