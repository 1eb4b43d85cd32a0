// Whether an observer sees a sign, from the light: what the sight rays measured (the sign's luminance and its
// background's as they reach the eye through the smoke, the veil of light the smoke scatters toward the eye
// included in both), judged by Adrian's visibility level, and beside it Jin's law from the same line's optical
// depth alone.
#pragma once
#include <limits>
#include <string>

#include "visibility/adrian.h"

namespace brume {

// What the rays from one eye to one sign measured at one instant.
struct SightMeasure {
    double distance = 0;             // eye to the sign's centre (m)
    double signLuminance = 0;        // cd/m², the mean over the sign's points whose rays met the sign
    double backgroundLuminance = 0;  // cd/m², the mean over the band around it
    double signError = 0, backgroundError = 0;  // cd/m², the standard errors of those means (the rays' noise)
    double seenShare = 0;            // the share of the sign's rays that met the sign (the rest met something before)
    double solidAngle = 0;           // sr, of the sign from the eye (projected, its far side hidden)
    double opticalDepth = 0;         // ∫K along the line to the sign's centre
    double coverage = 1;             // the share of that line where the smoke has data (DataCoverage): the rest
                                     // lies in its simulation's domain, without data, and adds nothing to ∫K
    bool facing = true;              // the eye is on the sign's front side
    double viewCosine = 1;           // of the angle between the sign's front and the line to the eye
    double eyeExtinction = 0;        // K at the eye (as the optical depth counts it)
    double legibilityDistance = 0;   // m: the distance factor Z times the sign's height (EN 1838, ISO 3864)
};

struct VisibilityCriteria {
    AdrianObserver observer;
    double minimumLevel = 1;     // the visibility level (ΔL / ΔL_threshold) a sign must reach
    double minimumSeenShare = 0.5;  // of the sign's area left unhidden by walls or furniture
    // A sign is not called visible (by either criterion) along a line with less of it with data: what is
    // missing would only add smoke. 0: the rest taken for clear air.
    double minimumCoverage = 0.5;
    // Jin's law as FDSVisMap applies it, when asked: S times the cosine of the angle the eye sees the sign's
    // front at (a sign seen obliquely reads as nearer its threshold), S at most `jinCap` (FDS's 30 m cap of its
    // VISIBILITY). Neither by default: S = C / K.
    bool jinViewAngle = false;
    double jinCap = std::numeric_limits<double>::infinity();
    // Smokeview's local criterion: C / K at the eye at least this (m); 0: none.
    double leastLocalVisibility = 0;
};

// NoData: the sign would be visible if the line's stretch without data were clear air, which no one knows.
// NotTraced: no light traced (vismap -vj), Jin's law alone.
enum class Verdict { Visible, BelowThreshold, Hidden, Behind, NoData, NotTraced };
const char* verdictName(Verdict v);  // "visible", "below-threshold", "hidden", "behind", "no-data", "not-traced"

struct SightJudgement {
    double contrast = 0;             // (L_sign − L_background) / L_background
    double angularSize = 0;          // arc minutes: the side of a square of the sign's solid angle
    double threshold = 0;            // cd/m², Adrian's ΔL at the background's luminance and that size
    double visibilityLevel = 0;      // |L_sign − L_background| / threshold
    double levelError = 0;           // its standard error from the luminances' (the threshold taken as exact)
    Verdict verdict = Verdict::Hidden;
    double meanExtinction = 0;       // 1/m: the optical depth over the distance
    double jinDistance = 0;          // m: Jin's S = C / K with K that mean (infinite in clear air), capped and
                                     // times the view's cosine where the criteria say
    double jinDepthLimit = 0;        // the optical depth up to which S reaches the distance (C, or C times the
                                     // view's cosine; −1 where the cap keeps it short whatever the smoke)
    bool jinVisible = false;         // S ≥ the distance (optical depth ≤ the limit), on the sign's front, not hidden,
                                     // with data enough
    bool jinNoData = false;          // visible by Jin's law but for the line's stretch without data
    double localVisibility = 0;      // m: C / K at the eye (infinite in clear air), FDS's VISIBILITY with its
                                     // factor the sign's C
    bool localEnough = true;         // at least the criterion's least
    bool legible = false;            // within the legibility distance, facing, not hidden
};

SightJudgement judge(const SightMeasure& m, double jinConstant, const VisibilityCriteria& criteria);

}  // namespace brume
