// For the sky tests: ∫ f(d) cos θ dω over the upper hemisphere, by the midpoint rule in (cos θ, φ).
#pragma once
#include <cmath>
#include <glm/vec3.hpp>

namespace brume {

template <class F>
double horizontalIntegral(F f, int n = 600) {
    double sum = 0, dMu = 1.0 / n, dPhi = 3.14159265358979323846 / n;
    for (int i = 0; i < n; ++i) {
        double mu = (i + 0.5) * dMu, s = std::sqrt(1 - mu * mu);
        for (int j = 0; j < 2 * n; ++j) {
            double phi = (j + 0.5) * dPhi;
            sum += f(glm::dvec3(s * std::cos(phi), s * std::sin(phi), mu)) * mu;
        }
    }
    return sum * dMu * dPhi;
}

}  // namespace brume
