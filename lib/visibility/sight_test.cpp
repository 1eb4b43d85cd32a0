#include "visibility/sight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace brume {
namespace {

SightMeasure measure(double signL, double backgroundL, double distance, double opticalDepth) {
    SightMeasure m;
    m.distance = distance;
    m.signLuminance = signL;
    m.backgroundLuminance = backgroundL;
    m.seenShare = 1;
    m.solidAngle = 0.09 / (distance * distance);  // a 0.3 m square face-on
    m.opticalDepth = opticalDepth;
    return m;
}

// Jin's S = C/K for even smoke, K d the optical depth: exactly, and the verdict S ≥ d.
TEST(Sight, JinsLawFromTheOpticalDepth) {
    VisibilityCriteria c;
    for (double k : {0.1, 0.5, 1.0, 2.0}) {
        SightJudgement j = judge(measure(100, 10, 10, k * 10), 8, c);
        EXPECT_NEAR(j.meanExtinction, k, 1e-12);
        EXPECT_NEAR(j.jinDistance, 8 / k, 1e-12);
        EXPECT_EQ(j.jinVisible, 8 / k >= 10);
        EXPECT_EQ(judge(measure(100, 10, 10, k * 10), 3, c).jinVisible, 3 / k >= 10);
    }
    EXPECT_TRUE(std::isinf(judge(measure(100, 10, 10, 0), 8, c).jinDistance));
}

TEST(Sight, VisibilityLevelIsTheDifferenceOverAdriansThreshold) {
    VisibilityCriteria c;
    c.minimumLevel = 10;
    SightJudgement j = judge(measure(150, 20, 5, 0), 8, c);
    double arcmin = std::sqrt(0.09 / 25) * 180 * 60 / M_PI;
    EXPECT_NEAR(j.angularSize, arcmin, 1e-9);
    EXPECT_NEAR(j.contrast, 6.5, 1e-12);
    EXPECT_NEAR(j.threshold, adrianThreshold(20, arcmin, true, c.observer), 1e-12);
    EXPECT_NEAR(j.visibilityLevel, 130 / j.threshold, 1e-9);
    EXPECT_EQ(j.verdict, Verdict::Visible);
    SightMeasure noisy = measure(150, 20, 5, 0);
    noisy.signError = 3, noisy.backgroundError = 4;
    EXPECT_NEAR(judge(noisy, 8, c).levelError, 5 / j.threshold, 1e-12);
    // A veil of 20 cd/m² added to both lowers the contrast, not the difference; the threshold grows with
    // the background.
    SightJudgement veiled = judge(measure(170, 40, 5, 0), 8, c);
    EXPECT_LT(veiled.contrast, j.contrast);
    EXPECT_LT(veiled.visibilityLevel, j.visibilityLevel);
    // A faint sign, a darker sign (negative contrast), one hidden, one seen from behind.
    EXPECT_EQ(judge(measure(20.5, 20, 5, 0), 8, c).verdict, Verdict::BelowThreshold);
    SightJudgement darker = judge(measure(2, 20, 5, 0), 3, c);
    EXPECT_LT(darker.contrast, 0);
    EXPECT_NEAR(darker.threshold, adrianThreshold(20, arcmin, false, c.observer), 1e-12);
    SightMeasure hidden = measure(150, 20, 5, 0);
    hidden.seenShare = 0.4;
    EXPECT_EQ(judge(hidden, 8, c).verdict, Verdict::Hidden);
    EXPECT_FALSE(judge(hidden, 8, c).jinVisible);
    SightMeasure behind = measure(150, 20, 5, 0);
    behind.facing = false;
    EXPECT_EQ(judge(behind, 8, c).verdict, Verdict::Behind);
    EXPECT_FALSE(judge(behind, 8, c).jinVisible);
    EXPECT_STREQ(verdictName(Verdict::BelowThreshold), "below-threshold");
}

// A line mostly through a simulation's domain without data: what is missing can only add smoke, so a sign seen
// along it is "no data", one not seen stays not seen; -vc 0 takes the rest for clear air.
TEST(Sight, ALineMostlyWithoutDataIsNotCalledVisible) {
    VisibilityCriteria c;
    SightMeasure m = measure(150, 20, 5, 0.5);
    m.coverage = 0.3;
    SightJudgement j = judge(m, 8, c);
    EXPECT_EQ(j.verdict, Verdict::NoData);
    EXPECT_FALSE(j.jinVisible);
    EXPECT_TRUE(j.jinNoData);
    EXPECT_STREQ(verdictName(j.verdict), "no-data");
    SightMeasure faint = measure(20.01, 20, 5, 20);
    faint.coverage = 0.3;
    EXPECT_EQ(judge(faint, 8, c).verdict, Verdict::BelowThreshold);
    EXPECT_FALSE(judge(faint, 8, c).jinNoData);  // 20 > C already
    m.coverage = 0.5;  // half the line known: as the criterion says
    EXPECT_EQ(judge(m, 8, c).verdict, Verdict::Visible);
    m.coverage = 0;
    c.minimumCoverage = 0;
    EXPECT_EQ(judge(m, 8, c).verdict, Verdict::Visible);
    EXPECT_TRUE(judge(m, 8, c).jinVisible);
}

// The criteria beside Adrian's: FDSVisMap's form of Jin's law (S capped, times the view's cosine), Smokeview's
// local visibility C / K at the eye, and a sign's legibility distance (Z times its height).
TEST(Sight, FdsVisMapsJinLocalVisibilityAndLegibility) {
    VisibilityCriteria c;
    SightMeasure m = measure(100, 10, 10, 2);  // S = 8 · 10 / 2 = 40 m at 10 m
    m.viewCosine = 0.5;
    m.eyeExtinction = 0.4;
    m.legibilityDistance = 200 * 0.2;  // an emitting sign 0.2 m high
    SightJudgement plain = judge(m, 8, c);
    EXPECT_NEAR(plain.jinDistance, 40, 1e-12);
    EXPECT_TRUE(plain.jinVisible);
    EXPECT_NEAR(plain.localVisibility, 20, 1e-12);
    EXPECT_TRUE(plain.localEnough);
    EXPECT_TRUE(plain.legible);
    c.jinCap = 30;
    EXPECT_NEAR(judge(m, 8, c).jinDistance, 30, 1e-12);
    c.jinViewAngle = true;  // 30 x 0.5 = 15 m: still beyond 10 m
    EXPECT_NEAR(judge(m, 8, c).jinDistance, 15, 1e-12);
    EXPECT_TRUE(judge(m, 8, c).jinVisible);
    m.opticalDepth = 4.5;  // S = 17.8 m, x 0.5 = 8.9 m: short of 10 m (the depth limit is C x 0.5 = 4)
    EXPECT_FALSE(judge(m, 8, c).jinVisible);
    EXPECT_NEAR(judge(m, 8, c).jinDepthLimit, 4, 1e-12);
    m.distance = 20;  // beyond what the cap x 0.5 reaches in any smoke
    EXPECT_EQ(judge(m, 8, c).jinDepthLimit, -1);
    m.opticalDepth = 0;
    EXPECT_FALSE(judge(m, 8, c).jinVisible);  // clear air, yet 15 m < 20 m
    c.leastLocalVisibility = 25;
    EXPECT_FALSE(judge(m, 8, c).localEnough);
    m.distance = 50;
    EXPECT_FALSE(judge(m, 8, c).legible);
    m.viewCosine = 0, m.opticalDepth = 0, c.jinCap = std::numeric_limits<double>::infinity();
    EXPECT_EQ(judge(m, 8, c).jinDistance, 0);  // edge-on: no NaN from infinity times zero
}

}  // namespace
}  // namespace brume
