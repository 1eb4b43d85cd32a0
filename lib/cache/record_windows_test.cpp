// The windows of time records serve: as long as the light's change allows (-aa), halved from -at down to
// its 256th, from the instant a record is made; three records at the window's start, middle and end.
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

// The records of the window from t of light E(t), -aa .1, and how many were made.
struct Made {
    std::vector<Light> records;
    int made = 0;
};
Made recordsAt(const RecordWindows& windows, double t, const std::function<double(double)>& light) {
    Made out;
    out.records = windows.recordsAt(t, Kind{}, 0.1, [&](double at) {
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

// Where nothing changes in time, one record serves every instant; with -at 0, or at the last instant with
// data, a record serves its own instant alone.
TEST(RecordWindows, OneRecordWhereTimeDoesNotCountOrCannotGoOn) {
    auto flat = [](double) { return 1.0; };
    Made still = recordsAt(RecordWindows(false, 100, 32), 5, flat);
    ASSERT_EQ(still.records.size(), 1u);
    EXPECT_EQ(still.records[0].when.weightAt(-1e9), 1.0);
    for (auto [windows, t] : {std::pair{RecordWindows(true, 100, 0), 5.0}, {RecordWindows(true, 100, 32), 100.0}}) {
        Made one = recordsAt(windows, t, flat);
        ASSERT_EQ(one.records.size(), 1u);
        EXPECT_EQ(one.records[0].when.weightAt(t), 1.0);
        EXPECT_EQ(one.records[0].when.weightAt(std::nextafter(t, 1e9)), 0.0);
    }
}

// Light that changes linearly in time is straight over the longest window (three records made, at t, t + 16
// and t + 32), clipped at the last instant with data; lookups inside it get the light exactly (to rounding).
TEST(RecordWindows, LinearLightTakesTheLongestWindow) {
    auto linear = [](double t) { return 2 + 0.1 * t; };
    Made m = recordsAt(RecordWindows(true, 100, 32), 10, linear);
    ASSERT_EQ(m.records.size(), 3u);
    EXPECT_EQ(m.made, 3);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m.records[i].when.at, 10 + 16 * i);
    for (double t : {10.0, 13.3, 26.0, 41.9}) EXPECT_NEAR(lookup(m.records, t), linear(t), 1e-12) << t;
    EXPECT_TRUE(std::isnan(lookup(m.records, 42)));
    EXPECT_TRUE(std::isnan(lookup(m.records, 9.9)));
    Made clipped = recordsAt(RecordWindows(true, 20, 32), 10, linear);
    EXPECT_EQ(clipped.records.back().when.at, 20);
}

// Light E(t) = 1 + (t/10)² from t = 0: the middle record departs from the chord of a window Δ long by Δ²/400,
// within -aa of the brightest, 1 + Δ²/100, where Δ²/400 ≤ .1 (1 + Δ²/100), Δ ≤ 8.2 s: from 32 s, halved to 16
// and 8 s (two more records). The interpolation through the three errs by at most a quarter of the chord's
// departure, E''h²/8 = .04 with h = 4 s, a quarter of -aa of the brightest.
TEST(RecordWindows, BendingLightHalvesTheWindowUntilItIsStraightWithinTheAccuracy) {
    auto bend = [](double t) { return 1 + t * t / 100; };
    Made m = recordsAt(RecordWindows(true, 100, 32), 0, bend);
    ASSERT_EQ(m.records.size(), 3u);
    EXPECT_EQ(m.made, 5);
    EXPECT_EQ(m.records.back().when.at, 8);
    for (double t = 0; t < 8; t += 0.25) EXPECT_NEAR(lookup(m.records, t), bend(t), 0.25 * 0.1 * bend(8)) << t;
}

// A step (a door closing at 5 s): windows from before it shrink until they end before it, or, from right
// before it, are as short as windows get, 32/256 s: the step is never smeared further.
TEST(RecordWindows, AStepIsNotSmearedPastItsInstantByMoreThanTheShortestWindow) {
    auto step = [](double t) { return t < 5 ? 1.0 : 3.0; };
    for (double t : {0.0, 3.0, 4.9, 4.99}) {
        Made m = recordsAt(RecordWindows(true, 100, 32), t, step);
        double end = m.records.back().when.to;
        EXPECT_LE(end, std::max(5.0, t + 32.0 / 256)) << t;
        if (end <= 5)
            for (double u = t; u < end; u += 0.01) EXPECT_EQ(lookup(m.records, u), 1.0) << t << " " << u;
    }
}
