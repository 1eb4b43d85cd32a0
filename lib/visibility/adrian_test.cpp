#include "visibility/adrian.h"

#include <gtest/gtest.h>

#include <cmath>

namespace brume {
namespace {

// Values worked by hand from Adrian's formulas (α = 10′, L_b = 1 cd/m²: √Φ = log(4.1925) + 0.1684 = 0.79087,
// √L = 0.05946) and for the table by an independent implementation of them; 1e-5 relative is their
// printed precision.
TEST(Adrian, ThresholdsOfWorkedExamples) {
    EXPECT_NEAR(adrianBasicThreshold(1, 10), 0.049908, 1e-5 * 0.049908);
    EXPECT_NEAR(adrianTimeConstant(1, 10), 0.124523, 1e-5);
    EXPECT_NEAR(adrianPolarityFactor(1, 10), 0.613965, 1e-5);
    AdrianObserver rp8{60, 0.2};
    EXPECT_NEAR(adrianThreshold(1, 10, true, rp8), 0.143194, 1e-5 * 0.143194);
    EXPECT_NEAR(adrianThreshold(1, 10, false, rp8), 0.087916, 1e-5 * 0.087916);
    EXPECT_NEAR(adrianThreshold(1, 10, true, {30, 0.2}), 0.084708, 1e-5 * 0.084708);
    struct Row { double arcmin, lb, basic, a, fcp, positive, negative; };
    for (Row r : {Row{4, 1, 0.171966, 0.152075, 0.808344, 0.535290, 0.432698},
                  Row{10, 0.1, 0.014309, 0.142023, 0.559383, 0.043268, 0.024203},
                  Row{10, 0.001, 0.003689, 0.175216, 0.5, 0.012236, 0.006118},
                  Row{10, 10, 0.260772, 0.111774, 0.714842, 0.718806, 0.513832},
                  Row{7.4554, 1, 0.071250, 0.132114, 0.678648, 0.209211, 0.141981}}) {
        SCOPED_TRACE(testing::Message() << r.arcmin << "' at " << r.lb << " cd/m2");
        EXPECT_NEAR(adrianBasicThreshold(r.lb, r.arcmin), r.basic, 2e-6 + 1e-5 * r.basic);
        EXPECT_NEAR(adrianTimeConstant(r.lb, r.arcmin), r.a, 2e-6);
        EXPECT_NEAR(adrianPolarityFactor(r.lb, r.arcmin), r.fcp, 2e-6);
        EXPECT_NEAR(adrianThreshold(r.lb, r.arcmin, true, rp8), r.positive, 2e-6 + 1e-5 * r.positive);
        EXPECT_NEAR(adrianThreshold(r.lb, r.arcmin, false, rp8), r.negative, 2e-6 + 1e-5 * r.negative);
    }
}

TEST(Adrian, SmallerDarkerOlderNeedsMore) {
    AdrianObserver young{25, 2}, old{70, 2};
    EXPECT_GT(adrianThreshold(1, 5, true, young), adrianThreshold(1, 20, true, young));  // Ricco: smaller targets
    EXPECT_GT(adrianThreshold(1, 10, true, old), adrianThreshold(1, 10, true, young));
    EXPECT_GT(adrianThreshold(1, 10, true, {25, 0.1}), adrianThreshold(1, 10, true, young));  // a glance
    // Weber's law: the threshold contrast ΔL/L_b falls as the light grows, from mesopic to photopic.
    double previous = 1e9;
    for (double lb : {0.001, 0.01, 0.1, 1.0, 10.0, 100.0}) {
        double contrast = adrianThreshold(lb, 10, true, young) / lb;
        EXPECT_LT(contrast, previous) << lb;
        previous = contrast;
    }
    // No light at all is the darkest background, not a division by zero.
    double dark = adrianThreshold(0, 10, true, young);
    EXPECT_TRUE(std::isfinite(dark) && dark > 0);
    EXPECT_TRUE(std::isfinite(adrianThreshold(1, 0, false, young)));
}

}  // namespace
}  // namespace brume
