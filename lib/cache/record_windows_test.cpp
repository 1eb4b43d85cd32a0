// The windows of time records serve: from an open record of one instant, as long as the light's change
// allows (-aa), halved from -at down to its 4096th; three records at the window's start, middle and end, and
// the end again, open for the next window.
#include "cache/record_windows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace brume;

namespace {

// A record of one number, the light at its instant.
struct Light {
    double value = 0;
    RecordTime when;
};

// The kind of record the windows are made for: its brightness, and zones that need no sharing.
struct Kind {
    static double brightnessOf(const Light& r) { return r.value; }
    static void shareZone(std::vector<Light>&) {}
};

// The records of the window from an open record of instant t of light E(t), -aa .1, and how many were made
// (the open record's not counted).
struct Made {
    std::vector<Light> records;
    int made = 0;
};
Made windowFrom(const RecordWindows& windows, double t, const std::function<double(double)>& light) {
    Made out;
    Light open{light(t), RecordTime::instant(t)};
    out.records = windows.windowFrom(open, Kind{}, 0.1, [&](double at) {
        ++out.made;
        return Light{light(at), {}};
    });
    return out;
}

// The value a lookup at t interpolates from the records.
double lookup(const std::vector<Light>& records, double t) {
    double sum = 0, total = 0;
    for (const Light& r : records) sum += r.value * r.when.weightAt(t), total += r.when.weightAt(t);
    return total > 0 ? sum / total : NAN;
}

}  // namespace

// A record is first made for its instant alone, or for every instant where nothing changes; an open record
// starts windows that reach instants after its own, within -at and before the last instant with data.
TEST(RecordWindows, ARecordIsFirstOfItsInstantAlone) {
    auto one = [](double) { return Light{1, {}}; };
    EXPECT_EQ(RecordWindows(false, 100, 32).recordAt(5, one).when.weightAt(-1e9), 1.0);
    Light first = RecordWindows(true, 100, 32).recordAt(5, one);
    EXPECT_EQ(first.when.weightAt(5), 1.0);
    EXPECT_EQ(first.when.weightAt(std::nextafter(5.0, 9.0)), 0.0);
    RecordWindows windows(true, 100, 32);
    EXPECT_TRUE(windows.opens());
    EXPECT_TRUE(windows.reaches(5, 6));
    EXPECT_FALSE(windows.reaches(5, 5));
    EXPECT_FALSE(windows.reaches(5, 37));
    EXPECT_FALSE(windows.reaches(100, 101));
    EXPECT_FALSE(RecordWindows(true, 100, 0).opens());
    EXPECT_FALSE(RecordWindows(false, 100, 32).opens());
}

// Light that changes linearly in time is straight over the longest window (two records made, at t + 16 and
// t + 32; the open one is its start), clipped at the last instant with data; lookups inside it get the light
// exactly (to rounding); its end is made again as a record of its instant alone, for the next window.
TEST(RecordWindows, LinearLightTakesTheLongestWindow) {
    auto linear = [](double t) { return 2 + 0.1 * t; };
    Made m = windowFrom(RecordWindows(true, 100, 32), 10, linear);
    ASSERT_EQ(m.records.size(), 4u);
    EXPECT_EQ(m.made, 2);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m.records[i].when.at, 10 + 16 * i);
    std::vector<Light> window(m.records.begin(), m.records.begin() + 3);
    for (double t : {10.0, 13.3, 26.0, 41.9}) EXPECT_NEAR(lookup(window, t), linear(t), 1e-12) << t;
    EXPECT_TRUE(std::isnan(lookup(window, 42)));
    EXPECT_TRUE(std::isnan(lookup(window, 9.9)));
    EXPECT_EQ(m.records[3].when.weightAt(42), 1.0);
    EXPECT_EQ(m.records[3].value, linear(42));
    EXPECT_EQ(windowFrom(RecordWindows(true, 20, 32), 10, linear).records[2].when.at, 20);
}

// Light E(t) = 1 + (t/10)² from t = 0: over a window Δ long the halves' changes differ by Δ²/200, within -aa
// of the brightest, 1 + Δ²/100, where Δ²/200 ≤ .1 (1 + Δ²/100), Δ ≤ 5 s: from 32 s, halved to 16, 8 and 4 s
// (three more records). The interpolation through the three errs by at most E''h²/8 = .01 with h = 2 s, an
// eighth of the halves' difference.
TEST(RecordWindows, BendingLightHalvesTheWindowUntilItIsStraightWithinTheAccuracy) {
    auto bend = [](double t) { return 1 + t * t / 100; };
    Made m = windowFrom(RecordWindows(true, 100, 32), 0, bend);
    EXPECT_EQ(m.made, 5);
    EXPECT_EQ(m.records[2].when.at, 4);
    std::vector<Light> window(m.records.begin(), m.records.begin() + 3);
    for (double t = 0; t < 4; t += 0.25) EXPECT_NEAR(lookup(window, t), bend(t), 0.0101) << t;
}

// A step anywhere in a window (from 1 to 1.3 at 7 s, inside the last quarter of a window from 0 to 8 s, where
// the middle record does not see it): the halves' changes, 0 and .3, differ by more than -aa: halved, to
// windows that end before the step; lookups within -aa of the light everywhere.
TEST(RecordWindows, AStepInAWindowsHalfIsNotInterpolatedAcross) {
    auto step = [](double t) { return t < 7 ? 1.0 : 1.3; };
    Made m = windowFrom(RecordWindows(true, 8, 32), 0, step);
    std::vector<Light> window(m.records.begin(), m.records.begin() + 3);
    EXPECT_LE(window[2].when.at, 7);
    for (double t = 0; t < window[2].when.to; t += 0.01) EXPECT_NEAR(lookup(window, t), step(t), 0.1 * 1.3) << t;
}

// A step (a door closing at 5 s): windows from before it shrink until they end before it, or, from right
// before it, are as short as windows get, 32/4096 s: the step is never smeared further.
TEST(RecordWindows, AStepIsNotSmearedPastItsInstantByMoreThanTheShortestWindow) {
    auto step = [](double t) { return t < 5 ? 1.0 : 3.0; };
    for (double t : {0.0, 3.0, 4.9, 4.99}) {
        Made m = windowFrom(RecordWindows(true, 100, 32), t, step);
        double end = m.records[2].when.to;
        EXPECT_LE(end, std::max(5.0, t + 32.0 / 4096)) << t;
        std::vector<Light> window(m.records.begin(), m.records.begin() + 3);
        if (end <= 5) {
            for (double u = t; u < end; u += 0.01) EXPECT_EQ(lookup(window, u), 1.0) << t << " " << u;
        }
    }
}
