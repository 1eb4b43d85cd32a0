// rfluxmtx's receivers: the surfaces of a receiver file grouped by modifier, each group with the
// hemisphere its contributions are binned over ("#@rfluxmtx h=… u=… o=…" before it: uniform, Tregenza's,
// Reinhart's or Klems' patches), its normal (the surfaces' area-weighted, away from the face that receives: a
// source's is opposite its direction) and up direction; and what each asks rcontrib for.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "contrib/contribution_run.h"
#include "contrib/flux_surfaces.h"

namespace brume {

struct FluxReceiver {
    std::string modifier;
    FluxSettings settings;    // the hemisphere, its hand and size, up, output
    glm::dvec3 normal{0};     // Σ area × normal of its surfaces
    bool sources = true;      // all its surfaces are sources
    std::vector<std::string> narrowSources;  // sources not of 180°
};

// The receivers of a receiver file, in order. Throws Error (file:line) for a bad #@rfluxmtx line, a surface
// with bad arguments, no receiver at all.
std::vector<FluxReceiver> readReceivers(const std::string& path);

// Adds what `r` asks rcontrib for to `run`: the bins' definitions and parameters, their count and
// expression, and the modifier; and to `words` the same as rcontrib's options. Throws Error for a
// hemisphere Brume has no bins for yet (Shirley-Chiu, CIE) or one binned over a source narrower than 180°.
void addReceiver(const FluxReceiver& r, ContributionRun& run, std::vector<std::string>& words);

}  // namespace brume
