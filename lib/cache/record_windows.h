// The windows of time the records of a scene that changes in time serve (RecordTime): made lazily, as a run
// moving forward in time asks for them.
//
// A record is first made for its own instant alone, and left open: where a later lookup, within -at seconds,
// finds no record of its instant but an open one that holds it, a window is made from the open record's
// instant with its samples (its request's seed: the same rays, so the records differ by how the light
// changed, little by their noise): the light is traced at the window's middle and end, the window is as long
// as its light allows — the longest whose halves' changes of light differ by at most -aa of the brightest of
// the three records, halved until they do, down to kHalvings halvings —, and its end is left open in turn.
// Lookups interpolate linearly between the two records nearest in time: where the light bends evenly they err
// by about an eighth of -aa; where it turns at once (a kink, a step such as a door closing) by at most -aa,
// the change of the half it turns in, or it is kept within the shortest window. A chain of windows, the light
// continuous from one to the next, each costing two records where a record per instant would cost one per
// frame. A record no later instant needs costs one. Where nothing changes in time, one record serves every
// instant.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "cache/record_request.h"
#include "cache/record_time.h"

namespace brume {

// A record of one instant that a window may start from, with the request it was made for.
template <class Record>
struct OpenRecord {
    Record record;
    RecordRequest request;
};

class RecordWindows {
public:
    static constexpr int kHalvings = 12;

    // Records of one instant each where `timed` (smoke that evolves, with data up to `last`), open for windows
    // up to `longest` s where that is positive; one record for every instant where nothing changes.
    RecordWindows(bool timed, double last, double longest) : timed_(timed), last_(last), longest_(timed ? longest : 0) {}

    // Whether records of one instant are left open for windows.
    bool opens() const { return longest_ > 0; }
    // Whether a window from an open record of instant `from` may serve instant t.
    bool reaches(double from, double t) const { return from < t && t < from + longest_ && from < last_; }
    // The earliest instant a window serving t may start from: open records (and the smoke) of earlier instants
    // serve a run at t no more.
    double openSince(double t) const { return t - longest_; }

    // The record of instant t, made by make(t): for every instant where nothing changes, else for t alone.
    template <class Make>
    auto recordAt(double t, const Make& make) const {
        auto record = make(t);
        record.when = timed_ ? RecordTime::instant(t) : RecordTime::always();
        return record;
    }

    // The records of the window from `open`'s instant (its record, the middle's and the end's, made by
    // make(instant) with its samples and sharing its zone, Kind::shareZone), then the end's again, of its
    // instant alone: open for the next window. `accuracy`: -aa.
    template <class Record, class Kind, class Make>
    std::vector<Record> windowFrom(const Record& open, const Kind& kind, double accuracy, const Make& make) const {
        const double from = open.when.at, shortest = longest_ / (1 << kHalvings);
        double to = std::min(from + longest_, last_);
        std::vector<Record> three{open, make(0.5 * (from + to)), make(to)};
        while (!straight(three, kind, accuracy) && (to - from) / 2 >= shortest) {
            to = 0.5 * (from + to);
            three[2] = std::move(three[1]);
            three[1] = make(0.5 * (from + to));
        }
        kind.shareZone(three);
        const double instants[3] = {from, 0.5 * (from + to), to};
        for (int i = 0; i < 3; ++i) three[i].when = RecordTime{instants[i], from, to, (to - from) / 2};
        Record next = three[2];
        next.when = RecordTime::instant(to);
        three.push_back(std::move(next));
        return three;
    }

private:
    template <class Record, class Kind>
    static bool straight(const std::vector<Record>& three, const Kind& kind, double accuracy) {
        double a = kind.brightnessOf(three[0]), m = kind.brightnessOf(three[1]), b = kind.brightnessOf(three[2]);
        return std::abs((b - m) - (m - a)) <= accuracy * std::max({a, m, b});
    }

    bool timed_;
    double last_;
    double longest_;
};

}  // namespace brume
