// Real spherical harmonics of orders 0 to 2 (nine functions, orthonormal over the sphere), and what a
// Henyey–Greenstein phase function does to them: by the Funk–Hecke theorem, convolving Y_lm with a phase
// function of asymmetry g scales it by g^l (the phase function's l-th Legendre moment).
#pragma once
#include <array>

#include <glm/vec3.hpp>

namespace brume {

constexpr int kShCount = 9;
// Y_0, the constant function: a coefficient c_0 is the mean over the sphere times 4π Y_0.
constexpr double kShY0 = 0.28209479177387814;
// The order l of the k-th function.
constexpr int shOrder(int k) { return k == 0 ? 0 : k < 4 ? 1 : 2; }

// Y_k(d) for unit d, k = 0 … 8 in the order (l, m) = (0,0), (1,−1), (1,0), (1,1), (2,−2), (2,−1), (2,0),
// (2,1), (2,2).
inline std::array<double, kShCount> shBasis(const glm::dvec3& d) {
    const double x = d.x, y = d.y, z = d.z;
    return {kShY0,
            0.4886025119029199 * y,
            0.4886025119029199 * z,
            0.4886025119029199 * x,
            1.0925484305920792 * x * y,
            1.0925484305920792 * y * z,
            0.31539156525252005 * (3 * z * z - 1),
            1.0925484305920792 * x * z,
            0.5462742152960396 * (x * x - y * y)};
}

}  // namespace brume
