// Brume's reinhartb.cal's rbin computed natively: the same operations on the same doubles in the same order as
// its expressions, so the same bins to the last bit, for rcontrib's commonest bins (rfluxmtx's sky and window
// hemispheres: Tregenza's and Reinhart's patches in a frame). Evaluating the .cal per contribution was 15 % of
// an annual run's time. Without jitter (JTR 0) only; ModifierBins falls back to the .cal otherwise.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

// reinhartb.cal's parameters: MF, RHS, the surface's normal rN (away from its face) and up direction U.
struct ReinhartFrame {
    double mf = 1, rhs = 1;
    glm::dvec3 normal{0, 0, -1}, up{0, 1, 0};
};

class ReinhartBins {
public:
    explicit ReinhartBins(const ReinhartFrame& frame);
    // rbin for the unit direction d toward the source: 0.. from the hemisphere's horizon up, −1 behind it.
    double bin(const glm::dvec3& d) const;

private:
    ReinhartFrame f_;
    double height_;              // b_height
    std::vector<double> count_;  // b_count per row, 0 … 7 MF
    std::vector<double> first_;  // b_first per row
};

}  // namespace brume
