// The warps' draws follow the densities warp.h states for them (chi-square, sampling/testing.h). The cosine
// hemisphere (and with it the concentric disk it lifts) and the whole sphere (a cone of 1 − cos = 2) are the
// harness's own controls (chi_square_test.cpp); uniformTriangle is tested through the sources it places points
// on (light_test.cpp: polygons sampled by area).
#include "sampling/warp.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;
using namespace brume::sampling::testing;

namespace {

// Draws of uniformCone about `axis`, counted in `grid`: 2×10⁵ draws in 20×40 cells (a density 10% off over a
// tenth of the cone fails).
void expectConeIsUniform(double halfAngle, const dvec3& axis, DirectionOptions grid) {
    const double oneMinusCos = 1 - std::cos(halfAngle);
    const Frame frame(axis);
    auto sample = [&](double u, double v) { return frame.toWorld(uniformCone(u, v, oneMinusCos)); };
    auto density = [&](const dvec3& d) {
        return 1 - glm::dot(d, axis) <= oneMinusCos ? 1 / (2 * std::numbers::pi * oneMinusCos) : 0.0;
    };
    SCOPED_TRACE(halfAngle);
    grid.draws = 200'000, grid.rings = 20, grid.sectors = 40;
    expectSamplesFollowDensity(sample, density, grid);
}

}  // namespace

// A wide cone (60°, its edge across cells of a grid about z), and the sun's (0.27°) in a grid over a cap of
// twice its angle about it (over the whole sphere it would fill a fraction of one cell).
TEST(Warp, ConeDrawsAreUniformInTheCone) {
    expectConeIsUniform(std::numbers::pi / 3, glm::normalize(dvec3(0.3, 0.1, 1)), {});
    const dvec3 sun = glm::normalize(dvec3(-0.2, 0.6, 0.4));
    expectConeIsUniform(0.0093 / 2, sun, {.axis = sun, .maxAngle = 0.0093});
}
