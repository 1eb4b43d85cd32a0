// The windows of time the records of a scene that changes in time serve (RecordTime), and the records of
// one window.
//
// A record made at instant t serves the window from t forward (a run moves forward in time: a walk through a
// fire, a visibility study's instants), at most `longest` seconds (-at) and within the instants where the
// smoke has data. A window is as long as its light allows: the longest whose middle record's light departs
// from the straight line between its ends by at most -aa of the brightest of the three (lookups,
// interpolating through the three, err by about a quarter of that where the light bends evenly), halved
// until it does, down to kHalvings halvings (a change as sudden as a door closing is then kept within that
// window). At the last instant with data, and with `longest` 0, a record serves its own instant alone.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "cache/record_time.h"

namespace brume {

struct TimeWindow {
    double from, to;  // [from, to), or the one instant from where to == from
};

class RecordWindows {
public:
    static constexpr int kHalvings = 8;

    // Each instant its own records where `timed` (smoke that evolves, with data up to `last`) and `longest` is
    // 0, windows up to `longest` s where it is positive; one record for every instant where nothing changes.
    RecordWindows(bool timed, double last, double longest) : timed_(timed), last_(last), longest_(timed ? longest : 0) {}

    bool timed() const { return timed_; }
    // The longest window from instant t (the instant alone at the last instant with data).
    TimeWindow longestAt(double t) const {
        if (!(longest_ > 0) || t >= last_) return {t, t};
        return {t, std::min(t + longest_, last_)};
    }

    // The records of the window from instant t, made by make(instant) and sharing one zone (Kind::shareZone),
    // with their RecordTime: one of every instant, one of t alone, or a window's three (at its start, middle and
    // end). `accuracy`: -aa.
    template <class Kind, class Make>
    auto recordsAt(double t, const Kind& kind, double accuracy, const Make& make) const {
        using Record = decltype(make(t));
        if (!timed_) return finish(std::vector<Record>{make(t)}, {0.0}, RecordTime::always(), kind);
        TimeWindow w = longestAt(t);
        if (w.from == w.to) return finish(std::vector<Record>{make(t)}, {t}, RecordTime::instant(t), kind);
        std::vector<Record> three{make(w.from), make(middle(w)), make(w.to)};
        const double shortest = longest_ / (1 << kHalvings);
        while (!straight(three, kind, accuracy) && (w.to - w.from) / 2 >= shortest) {
            three[2] = std::move(three[1]);
            w.to = middle(w);
            three[1] = make(middle(w));
        }
        return finish(std::move(three), {w.from, middle(w), w.to}, RecordTime{0, w.from, w.to, (w.to - w.from) / 2},
                      kind);
    }

private:
    static double middle(const TimeWindow& w) { return 0.5 * (w.from + w.to); }
    template <class Record, class Kind>
    static bool straight(const std::vector<Record>& three, const Kind& kind, double accuracy) {
        double a = kind.brightnessOf(three[0]), m = kind.brightnessOf(three[1]), b = kind.brightnessOf(three[2]);
        return std::abs(m - 0.5 * (a + b)) <= accuracy * std::max({a, m, b});
    }
    // Sets each record's time (`when`, at its own instant of `instants`) and shares their zone.
    template <class Record, class Kind>
    static std::vector<Record> finish(std::vector<Record> records, const std::vector<double>& instants,
                                      RecordTime when, const Kind& kind) {
        for (size_t i = 0; i < records.size(); ++i) {
            records[i].when = when;
            records[i].when.at = instants[i];
        }
        kind.shareZone(records);
        return records;
    }

    bool timed_;
    double last_;
    double longest_;
};

}  // namespace brume
