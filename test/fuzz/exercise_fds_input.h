// What the FDS input and sign-placement fuzz targets and the corpus replay do with an input: an .fds file read
// into groups and built into its geometry (fds2rad's), every wall, solid and vent finite; a sign list read and
// each sign's corners finite. Refusing with brume::Error is fine; anything not finite is a bug (trapped).
#pragma once
#include <cmath>
#include <cstdlib>
#include <istream>

#include "fds/case_geometry.h"
#include "visibility/sign_layout.h"

namespace brume::fuzz {

inline void checkFinite(const dvec3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
}

inline void exerciseFdsInput(std::istream& in) {
    CaseGeometry g = caseGeometry(readFdsInput(in, "fuzz.fds"));
    for (const CaseRectangle& r : g.walls)
        for (const dvec3& c : r.corners()) checkFinite(c);
    for (const CaseRectangle& r : g.vents)
        for (const dvec3& c : r.corners()) checkFinite(c);
    for (const CaseSolid& s : g.solids) checkFinite(s.box.lo), checkFinite(s.box.hi);
}

inline void exerciseSignPlacements(std::istream& in) {
    for (const SignPlacement& s : readSignPlacements(in, "fuzz_signs.txt"))
        for (const dvec3& c : s.corners()) checkFinite(c);
}

}  // namespace brume::fuzz
