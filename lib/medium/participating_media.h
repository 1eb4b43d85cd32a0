// What absorbs and scatters light along a ray at one instant of the scene: the homogeneous medium the ray is
// in (Radiance's global medium and the mists it crossed into, which the integrator follows) and the smoke
// volumes, which are where their grids say whatever the ray crossed. Extinction adds up; a scattering event
// picks one of them by its scattering coefficient.
#pragma once
#include <optional>
#include <vector>

#include "medium/homogeneous_medium.h"
#include "medium/null_collisions.h"
#include "medium/phase_mixture.h"
#include "medium/smoke.h"

namespace brume {

class ParticipatingMedia {
public:
    ParticipatingMedia() = default;
    explicit ParticipatingMedia(std::vector<SmokeVolume> smoke);

    bool hasSmoke() const { return !smoke_.empty(); }
    // Whether some smoke may lie on the ray between t = start and t = end (its grid's box is crossed).
    bool smokeAlong(const Ray& ray, double start, double end) const;
    // Whether some smoke is a flame (has a temperature).
    bool emits() const;
    // What the flames emit per unit length at p (see SmokeVolume::emission).
    Spectrum emission(const dvec3& p) const;

    // Flames as light sources: directions from `from` toward where they glow, for u0..u3 uniform in [0, 1) (none
    // where a point drawn is `from` itself), and their density per steradian; no flame: every direction's
    // density is 0. Points drawn in each smoke's EmissionCells (chosen in proportion to its power), and, from
    // inside the flames' box, half the directions uniform over the sphere: there the points drawn near `from`
    // give directions of density ∝ t³ whose light, ∝ t, is not small (the 1/r² of a source one stands in), and
    // the sphere's 1/4π bounds their weights. (A wall's pixel beside make demo's plume at -ab 1, 5000 paths:
    // one 23 times the mean without.)
    bool hasFlames() const { return !flames_.empty(); }
    std::optional<dvec3> sampleFlameDirection(const dvec3& from, double u0, double u1, double u2, double u3) const;
    double flameDirectionDensity(const dvec3& from, const dvec3& dir) const;
    const Bounds3& flameBox() const { return flameBox_; }
    // ∫ brightness(σ_a B) dV over the flames: their intensity, as a lamp's radiance × its size².
    double flamePower() const { return flamePower_; }
    // The light the flames emit toward ray.org along [start, end], ∫ T σ_a B dt with T from `start` through
    // `h` and the smoke, and in `transmittance` T over the whole stretch (both exact in T: the smokes' densities
    // along the ray, DensityProfile). `points` distances stratified over where the flames' first collision
    // falls, in their densest and their clearest band (DepthCollision, a mixture of the two), each weighing B
    // times T from the flames to the point over theirs: at most B (1 − e^{−τ}), so even flames are right per
    // ray however thick (their near side) or thin (all along). Where the temperature varies, half the draws
    // follow what draws at 2·points places would weigh (PiecewiseConstant), so that the hot core a ray
    // crosses, or the hot side of a ramping edge, gets the draws its light asks for. 16 points by default (view
    // rays): through the core of make demo's plume a ray's spread is 0.9 %, 2.5 % with 8.
    Spectrum emittedAlong(const Ray& ray, double start, double end, const HomogeneousMedium& h, Random& random,
                          Spectrum& transmittance, int points = 16) const;
    // A distance in [start, end] where the smoke's first collision falls (σ_t e^{−τ}, conditioned to fall before
    // `end`, τ exact: DepthCollision; in its densest band, half in its clearest where they differ, as
    // emittedAlong draws), for `u` in [0, 1), and its density; none where no smoke is. Weighing σ_s T by it
    // leaves about the albedo times the chance of a collision at all.
    std::optional<std::pair<double, double>> smokeCollision(const Ray& ray, double start, double end, double u) const;
    // Whether anything on the ray can scatter light (or only absorbs it).
    bool scatters(const HomogeneousMedium& h) const;
    // The Henyey–Greenstein g of what scatters along [start, end], to guide sampling: the mean g of the
    // scattering smoke whose box the ray crosses, weighted by the brightness of its albedo, else that of `h`.
    double asymmetry(const Ray& ray, double start, double end, const HomogeneousMedium& h) const;

    // Stretches of [start, end] in order, each with a majorant of the extinction of `h` (if given) plus the smoke:
    // in every band (Band::Largest), or in the band of least positive extinction of each medium
    // (Band::Smallest, which makes distance sampling reach as far as the clearest band sees), with a minorant
    // in that band (the homogeneous medium's extinction plus the smoke's cells' least). Stretches of majorant 0
    // are left out.
    enum class Band { Largest, Smallest };
    void majorants(const Ray& ray, double start, double end, const HomogeneousMedium* h,
                   std::vector<MajorantSegment>& out, Band band = Band::Largest) const;
    // ∫K dt between start and end through `h` and the smoke, K each one's as a study quotes one number
    // (QuotedExtinction; the homogeneous medium's photopic mean): the optical depth of a line of sight.
    double quotedDepth(const Ray& ray, double start, double end, const HomogeneousMedium& h, QuotedExtinction quoted) const;
    // K at a point, as quotedDepth counts it: the local extinction FDS's VISIBILITY (C / K) divides by.
    double quotedExtinction(const dvec3& p, const HomogeneousMedium& h, QuotedExtinction quoted) const;
    // The length of [start, end] through a simulation's domain where the smoke has no data (the longest of the
    // smokes', SmokeVolume::uncoveredLength).
    double uncoveredLength(const Ray& ray, double start, double end) const;
    // exp(−∫σ_t) of the smoke between start and end (SmokeVolume::transmittance: exact, no noise).
    Spectrum smokeTransmittance(const Ray& ray, double start, double end) const;
    // The same through `h` and the smoke (`h` in closed form).
    Spectrum transmittance(const Ray& ray, double start, double end, const HomogeneousMedium& h) const;
    // σ_t of the smoke at p.
    Spectrum smokeExtinction(const dvec3& p) const;
    // The scattering at p: each medium's σ_s times `scale`, with its phase function.
    void scattering(const dvec3& p, const HomogeneousMedium& h, const Spectrum& scale, PhaseMixture& out) const;

private:
    // The share of the directions drawn uniformly over the sphere (sampleFlameDirection).
    double flameSphereShare(const dvec3& from) const;
    struct Flame {
        size_t volume;  // in smoke_ (an index: the media may be moved or copied)
        double share;   // of the draws
    };
    std::vector<SmokeVolume> smoke_;
    std::vector<Flame> flames_;
    Bounds3 flameBox_;
    double flamePower_ = 0;
};

}  // namespace brume
