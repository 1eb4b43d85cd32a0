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
        case Verdict::NotTraced: return "not-traced";
    }
    return "";
}

SightJudgement judge(const SightMeasure& m, double jinConstant, const VisibilityCriteria& criteria) {
    SightJudgement j;
    const double inf = std::numeric_limits<double>::infinity();
    j.meanExtinction = m.distance > 0 ? m.opticalDepth / m.distance : 0;
    // S = C / K, at most the cap, times the view's cosine where asked: visible while S ≥ the distance, that is
    // while the optical depth is at most C times that cosine (and the cap times it reaches the distance).
    const double view = criteria.jinViewAngle ? std::max(0.0, m.viewCosine) : 1.0;
    const double s = m.opticalDepth > 0 ? jinConstant * m.distance / m.opticalDepth : inf;
    j.jinDistance = view > 0 ? std::min(s, criteria.jinCap) * view : 0;
    j.jinDepthLimit = criteria.jinCap * view >= m.distance ? jinConstant * view : -1;
    j.localVisibility = m.eyeExtinction > 0 ? jinConstant / m.eyeExtinction : inf;
    j.localEnough = j.localVisibility >= criteria.leastLocalVisibility;
    // Jin's law sees walls too: only the light is left out.
    const bool known = m.coverage >= criteria.minimumCoverage;
    j.jinVisible = m.facing && m.seenShare >= criteria.minimumSeenShare && m.opticalDepth <= j.jinDepthLimit;
    j.legible = m.facing && m.seenShare >= criteria.minimumSeenShare && m.distance <= m.legibilityDistance;
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
