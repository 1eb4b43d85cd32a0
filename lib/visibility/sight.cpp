#include "visibility/sight.h"

#include <cmath>
#include <limits>

namespace brume {

const char* verdictName(Verdict v) {
    switch (v) {
        case Verdict::Visible: return "visible";
        case Verdict::BelowThreshold: return "below-threshold";
        case Verdict::Hidden: return "hidden";
        case Verdict::Behind: return "behind";
        case Verdict::NoData: return "no-data";
    }
    return "";
}

SightJudgement judge(const SightMeasure& m, double jinConstant, const VisibilityCriteria& criteria) {
    SightJudgement j;
    j.meanExtinction = m.distance > 0 ? m.opticalDepth / m.distance : 0;
    j.jinDistance = m.opticalDepth > 0 ? jinConstant * m.distance / m.opticalDepth : std::numeric_limits<double>::infinity();
    // Jin's law sees walls too: only the light is left out.
    const bool known = m.coverage >= criteria.minimumCoverage;
    j.jinVisible = m.facing && m.seenShare >= criteria.minimumSeenShare && m.opticalDepth <= jinConstant;
    j.jinNoData = j.jinVisible && !known;
    j.jinVisible = j.jinVisible && known;
    if (!m.facing) {
        j.verdict = Verdict::Behind;
        return j;
    }
    const double kArcminPerRadian = 180 * 60 / M_PI;
    j.angularSize = std::sqrt(std::max(0.0, m.solidAngle)) * kArcminPerRadian;
    const double difference = m.signLuminance - m.backgroundLuminance;
    j.contrast = m.backgroundLuminance > 0 ? difference / m.backgroundLuminance : 0;
    j.threshold = adrianThreshold(m.backgroundLuminance, j.angularSize, difference >= 0, criteria.observer);
    j.visibilityLevel = j.threshold > 0 ? std::abs(difference) / j.threshold : 0;
    j.levelError = j.threshold > 0 ? std::hypot(m.signError, m.backgroundError) / j.threshold : 0;
    if (m.seenShare < criteria.minimumSeenShare) j.verdict = Verdict::Hidden;
    else if (j.visibilityLevel < criteria.minimumLevel) j.verdict = Verdict::BelowThreshold;
    else j.verdict = known ? Verdict::Visible : Verdict::NoData;
    return j;
}

}  // namespace brume
