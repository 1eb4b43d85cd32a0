// Adrian's visibility model (W. Adrian, "Visibility of targets: model for calculation", Lighting Research &
// Technology 21(4), 1989, 181–188; the model of CIE 115's and ANSI/IES RP-8's small target visibility): the
// least luminance difference ΔL between a target and its background that an observer detects, from the
// background's luminance L_b (the eye adapted to it), the target's angular size α, the observer's age and how
// long the target is looked at. A target's visibility level is its ΔL over that threshold.
#pragma once

namespace brume {

struct AdrianObserver {
    double age = 60;       // years (23 to 75): RP-8's observer; older eyes need more contrast
    double seconds = 0.2;  // the observation time: one fixation, as RP-8's
};

// Adrian's threshold ΔL (cd/m²) for a target of angular size `arcmin` (minutes of arc, > 0) brighter
// (`positive`) or darker than a background of `background` cd/m² (> 0): k (√Φ/α + √L)² with k = 2.6 and
// Adrian's Φ (Ricco) and L (Weber) functions of each luminance range, times the time factor (a(α, L_b) + t)/t,
// the age factor, and for darker targets the polarity factor F_cp (with ΔL at t = 2 s, as RP-8). The constants
// are Adrian's (4.1925 in Φ's photopic range; RP-8-00 prints 4.2841, 1.4 % higher thresholds at 1 cd/m²).
// Backgrounds darker than this are taken as this (no light at all would make the threshold 0).
inline constexpr double kDarkest = 1e-6;
double adrianThreshold(double background, double arcmin, bool positive, const AdrianObserver& observer);

// The parts, for tests and for readers checking them against the paper.
double adrianBasicThreshold(double background, double arcmin);  // k (√Φ/α + √L)²
double adrianTimeConstant(double background, double arcmin);     // a(α, L_b), seconds
double adrianAgeFactor(double age);
double adrianPolarityFactor(double background, double arcmin);  // F_cp (< 1) for negative contrast

}  // namespace brume
