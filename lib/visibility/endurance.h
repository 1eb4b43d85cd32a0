// How long each sign stays visible from each eye as the smoke evolves, by the light (Adrian's visibility level)
// and by Jin's law: the last instant through which it was visible from the first, and when it was lost —
// interpolated between the instants around the loss where the criterion's own measure crossed its threshold
// (the visibility level falling to -vl; the optical depth rising to C), else only bracketed by them (the sign
// hidden, the line without data, seen from behind). And per eye, the same for "any sign": an escape route needs
// one sign in sight, not all.
#pragma once
#include <vector>

#include "visibility/study.h"

namespace brume {

struct Loss {
    enum class Kind { Never, AtFirst, Interpolated, Bracketed };
    Kind kind = Kind::Never;
    double after = 0;   // the last instant it was visible at (Interpolated, Bracketed; the last of all for Never)
    double before = 0;  // the first it was not (AtFirst: the first instant)
    double at = 0;      // Interpolated: when the measure crossed the threshold, between after and before
};
const char* lossKindName(Loss::Kind k);  // "never", "at-first", "interpolated", "bracketed"

class Endurance {
public:
    Endurance(size_t observers, size_t signs) : signs_(signs), light_(observers * signs), jin_(observers * signs),
                                               anyLight_(observers), anyJin_(observers) {}

    // The sight lines of the next instant (instants increasing), as `study` gave them.
    void add(double time, const std::vector<SightLine>& lines, const VisibilityStudy& study);

    const Loss& light(size_t line) const { return light_[line].loss; }
    const Loss& jin(size_t line) const { return jin_[line].loss; }
    // For each observer: some sign (any of the study's) in sight, by the light and by Jin's law.
    const Loss& anyLight(size_t observer) const { return anyLight_[observer].loss; }
    const Loss& anyJin(size_t observer) const { return anyJin_[observer].loss; }
    // The last instant through which the sign was visible from the first, 0 where it was not at the first.
    static double until(const Loss& loss) { return loss.kind == Loss::Kind::AtFirst ? 0 : loss.after; }

private:
    struct Track {
        bool started = false;
        double lastTime = 0, lastMeasure = 0;  // the instant before, while visible, and its measure
        Loss loss;
        // Visible or not at `time`; `measure` the criterion's own, `crossed` whether its threshold explains the
        // loss (then interpolated linearly in it toward `threshold`).
        void add(double time, bool visible, double measure, bool crossed, double threshold);
    };
    size_t signs_;
    std::vector<Track> light_, jin_, anyLight_, anyJin_;
};

}  // namespace brume
