// Draws of a piecewise-constant density follow the density it reports (chi-square, sampling/testing.h: 2×10⁵
// draws in 100 bins, bins of no weight and a heavy one included), which integrates to 1; the uniform share
// is a floor under every bin.
#include "sampling/piecewise_constant.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;
using namespace brume::sampling::testing;

TEST(PiecewiseConstant, DrawsFollowTheDensityAndTheUniformShareIsItsFloor) {
    const std::vector<double> weights = {0, 0, 3, 0.5, 0, 20, 1e-9, 0, 2, 0};
    for (double uniform : {0.5, 0.1, 1.0}) {
        SCOPED_TRACE(uniform);
        PiecewiseConstant p(weights, uniform);
        double integral = 0;
        for (int i = 0; i < 10000; ++i) {
            double x = (i + 0.5) / 10000;
            integral += p.density(x) / 10000;
            EXPECT_GE(p.density(x), uniform * (1 - 1e-12));
        }
        EXPECT_NEAR(integral, 1, 1e-9);
        EXPECT_EQ(p.density(-0.1), 0);
        EXPECT_EQ(p.density(1), 0);
        auto draw = [&](double u) -> std::optional<double> { return p.sample(u); };
        expectSamplesFollowDensity(draw, [&](double x) { return p.density(x); }, {.lo = 0, .hi = 1});
        EXPECT_LT(p.sample(0.999999999), 1);
        EXPECT_GE(p.sample(0), 0);
    }
}

TEST(PiecewiseConstant, NoWeightAtAllIsUniform) {
    PiecewiseConstant none(std::vector<double>{0, 0, 0}, 0.2), empty({}, 0.2);
    for (double x : {0.0, 0.3, 0.9}) {
        EXPECT_DOUBLE_EQ(none.density(x), 1);
        EXPECT_DOUBLE_EQ(empty.density(x), 1);
    }
    EXPECT_DOUBLE_EQ(none.sample(0.37), 0.37);
}
