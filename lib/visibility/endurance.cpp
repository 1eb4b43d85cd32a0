#include "visibility/endurance.h"

#include <algorithm>

namespace brume {

const char* lossKindName(Loss::Kind k) {
    switch (k) {
        case Loss::Kind::Never: return "never";
        case Loss::Kind::AtFirst: return "at-first";
        case Loss::Kind::Interpolated: return "interpolated";
        case Loss::Kind::Bracketed: return "bracketed";
    }
    return "";
}

void Endurance::Track::add(double time, bool visible, double measure, bool crossed, double threshold) {
    const bool first = !started;
    started = true;
    if (loss.kind != Loss::Kind::Never) return;  // lost already
    if (visible) {
        loss.after = lastTime = time, lastMeasure = measure;
        return;
    }
    loss.before = time;
    if (first) {
        loss.kind = Loss::Kind::AtFirst;
        return;
    }
    const double span = measure - lastMeasure;
    if (crossed && span != 0) {
        loss.kind = Loss::Kind::Interpolated;
        loss.at = lastTime + std::clamp((threshold - lastMeasure) / span, 0.0, 1.0) * (time - lastTime);
    } else {
        loss.kind = Loss::Kind::Bracketed;
    }
}

void Endurance::add(double time, const std::vector<SightLine>& lines, const VisibilityStudy& study) {
    const VisibilityCriteria& criteria = study.settings().criteria;
    for (size_t o = 0; o < anyLight_.size(); ++o) {
        bool anyLight = false, anyJin = false;
        for (size_t s = 0; s < signs_; ++s) {
            const size_t line = o * signs_ + s;
            const SightJudgement& j = lines[line].judgement;
            const SightMeasure& m = lines[line].measure;
            const bool seen = j.verdict == Verdict::Visible;
            light_[line].add(time, seen, j.visibilityLevel, j.verdict == Verdict::BelowThreshold, criteria.minimumLevel);
            // Jin's law lost by its optical depth alone: the line neither hidden nor without data.
            const bool deep = !j.jinVisible && !j.jinNoData && m.facing && m.seenShare >= criteria.minimumSeenShare &&
                              m.coverage >= criteria.minimumCoverage;
            jin_[line].add(time, j.jinVisible, m.opticalDepth, deep && j.jinDepthLimit >= 0, j.jinDepthLimit);
            anyLight = anyLight || seen;
            anyJin = anyJin || j.jinVisible;
        }
        anyLight_[o].add(time, anyLight, 0, false, 0);
        anyJin_[o].add(time, anyJin, 0, false, 0);
    }
}

}  // namespace brume
