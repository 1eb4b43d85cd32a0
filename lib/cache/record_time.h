// When a record holds: the instant its light is of, and the instants it serves. Where the scene changes in
// time, a record serves its own instant alone, or a window of them with the other records of its window (the
// light at the window's start, middle and end traced with the same samples, sharing one zone, as Ribardière
// 2010's spatio-temporal records hold three primary records; RecordWindows makes them): a lookup inside the
// window interpolates linearly in time between the two whose instants are nearest, each record's weight
// falling from 1 at its own instant to 0 at its neighbours'. Where nothing changes, one record serves every
// instant.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

namespace brume {

struct RecordTime {
    double at = 0;  // the instant its light is of (s)
    // The window it serves with the other records of its window: [from, to), or the one instant `at` where
    // to == from.
    double from = -std::numeric_limits<double>::infinity();
    double to = std::numeric_limits<double>::infinity();
    double spacing = std::numeric_limits<double>::infinity();  // between the instants of its window's records

    // Every instant (a scene where nothing changes in time).
    static RecordTime always() { return RecordTime{}; }
    // Instant `at` alone.
    static RecordTime instant(double at) { return RecordTime{at, at, at, 0}; }

    // Its weight in a lookup at instant t: linear in time from its own instant to its neighbours', 0 outside
    // its window (exactly 1 at every instant for a record of every instant).
    double weightAt(double t) const {
        if (from == to) return t == at ? 1.0 : 0.0;
        if (!(t >= from && t < to)) return 0.0;
        return std::max(0.0, 1 - std::abs(t - at) / spacing);
    }
    // Whether its window is over at instant t (a run that has moved on to t will not look it up).
    bool overAt(double t) const { return from == to ? at < t : to <= t; }
};

}  // namespace brume
