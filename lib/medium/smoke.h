// The `smoke` scene object: a density grid from OpenVDB files (one, or key frames in time) turned into a
// participating medium: extinction per unit density (K_m for soot in kg/m³), scattering albedo, Henyey–Greenstein g.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "medium/emission_cells.h"
#include "medium/grid_sequence.h"
#include "medium/majorant_grid.h"
#include "scene/scene.h"
#include "spectrum/blackbody.h"
#include "spectrum/spectrum.h"

namespace brume {

// What a `smoke` object says, read once per scene.
struct SmokeDescription {
    SourceLocation where;  // of the smoke object, and its name: for messages
    std::string name;
    std::shared_ptr<const GridSequence> frames;
    Spectrum extinctionPerDensity;  // σ_t per unit density, per band of the current spectral sampling
    Spectrum albedo;                // σ_s / σ_t
    double g = 0;                   // Henyey–Greenstein mean cosine (> 0 forward)
    // Flames: temperature (K) at the same key frames, or null. What the smoke absorbs it emits as a black body.
    std::shared_ptr<const GridSequence> temperature;
    // Soot (extinction=soot): K given at 633 nm, where FDS's mass extinction coefficient and the measurements
    // behind it are, and extinctionPerDensity that times sootExtinction(); else none.
    std::optional<double> extinctionAt633;
};

// Which K a study quotes for one number (Jin's law): at 633 nm, as FDS's VISIBILITY and FDSVisMap do (soot's K
// as given; any other smoke's photopic mean), or the photopic mean of every smoke's K, as the eye sees it.
enum class QuotedExtinction { At633nm, Photopic };

// Soot's extinction relative to its value at 633 nm, K(λ)/K(633) = (λ/633 nm)^−1.39 (Hottel's correlation for
// soot in the visible; bands' averages, in RGB the spectrum's colour): 1.20 in the photopic mean.
Spectrum sootExtinction();

// Reads a `smoke` object's arguments (see rtrace(1), "Smoke") and loads its grids, found along RAYPATH:
//   N [density=GRID] [temperature=GRID] [extinction=soot] file.vdb | … t1 file1.vdb t2 file2.vdb …   0
//   3|6|7 K K K [a a a [g]]
// A single file is static; key-frame times are the ones written (metadata such as FDS's fds_time_s is not
// read). Throws Error "file:line: bad smoke 'id': …".
SmokeDescription readSmoke(const SceneObject& object);

// Error ("file:line: smoke 'name': no data at …", naming its frames) where one of `times` is outside the key
// frames of smoke that evolves: before the first or after the last there is no data, and the nearest frame's
// soot is not to stand in for it. Programs call it before they write anything; SmokeVolume checks its own.
void checkInstants(const std::vector<SmokeDescription>& smoke, std::span<const double> times);

// What the smoke's key frames say of their data (DataCoverage::note): the first frame's that says anything, "" if
// none does.
std::string dataNote(const SmokeDescription& smoke);

// What programs tell the user of smoke whose simulation's domain has no data in part (DataCoverage): one
// message per such smoke object ("file:line: smoke 'name': …"), saying what the data are and that rays cross
// the rest as clear air. Empty where every smoke is whole, or claims no domain.
std::vector<std::string> noDataWarnings(const std::vector<SmokeDescription>& smoke);

// The smoke at one instant of the scene: what rays are tracked through. Thread-safe const members.
class SmokeVolume {
public:
    // Error at an instant outside the key frames (checkInstants). `voxelsPerCell`: the majorant grid's cell edge in voxels (MajorantGrid); 0 makes one cell of the whole
    // grid, which skips no empty space inside its box (for measuring what skipping saves).
    SmokeVolume(const SmokeDescription& smoke, double time, int voxelsPerCell = 8);

    // Where the density can be non-zero at some time (all key frames); empty for empty grids.
    const Bounds3& bounds() const { return bounds_; }
    double density(const dvec3& p) const;
    // σ_t at p, per band.
    Spectrum extinction(const dvec3& p) const { return description_.extinctionPerDensity * float(density(p)); }
    bool emits() const { return description_.temperature != nullptr; }
    // What the smoke emits per unit length at p: σ_a(p)·B(T(p)), B Planck's radiance (as emitted light adds
    // along a ray: ∫ T σ_a B dt).
    Spectrum emission(const dvec3& p) const { return emission(p, density(p)); }
    // The same where the density is known (a DensityProfile's, along a ray).
    Spectrum emission(const dvec3& p, double density) const;
    // Where the flames glow, for next-event estimation (empty where the smoke does not emit).
    const EmissionCells& flames() const { return flames_; }
    const Spectrum& extinctionPerDensity() const { return description_.extinctionPerDensity; }
    // The one K per unit density a study quotes (QuotedExtinction).
    double quotedExtinctionPerDensity(QuotedExtinction quoted) const;
    // The length of [tmin, tmax] along the ray through the domain of the simulation the smoke comes from where
    // it has no data (GridSequence::uncoveredLength): smoke no one knows, which rays cross as clear air.
    double uncoveredLength(const Ray& ray, double tmin, double tmax) const {
        return description_.frames->uncoveredLength(ray, tmin, tmax, time_);
    }
    // ∫ density dt between tmin and tmax, exactly (as transmittance() finds it).
    double densityIntegral(const Ray& ray, double tmin, double tmax) const;
    const Spectrum& albedo() const { return description_.albedo; }
    double g() const { return description_.g; }
    // Calls f(t0, t1, majorant, minorant) -> bool for consecutive stretches of [tmin, tmax] along the ray inside
    // the volume, where majorant ≥ σ_t in every band (0 where there is no smoke) and minorant ≤ σ_t in the
    // largest band; false from f stops the walk.
    template <typename F>
    void forEachBound(const Ray& ray, double tmin, double tmax, F&& f) const {
        majorant_.forEachBound(ray, tmin, tmax, [&](double t0, double t1, double most, double least) {
            return f(t0, t1, most * scale_, least * scaleDown_);
        });
    }

    // exp(−∫σ_t) between tmin and tmax, per band, without noise: the density's integral exactly (as
    // interpolated, GridSequence::integral) where a majorant cell's smoke is uneven, in closed form where it
    // is even, nothing where there is none. Ratio tracking, unbiased too, had a relative standard deviation
    // of √(e^{D/m} − 1) for a residual optical depth D tracked with m·D collisions: in the corridor of make
    // demo at t = 120 s view rays' errors were mostly that noise.
    Spectrum transmittance(const Ray& ray, double tmin, double tmax) const;
    // e^{−K ∫ρ} per band for `integral` = ∫ρ along a line.
    Spectrum transmittance(double integral) const;
    // The density along the ray over [tmin, tmax] as the same walk finds it: constant in even cells, the
    // voxels' cubics in uneven ones (DensityProfile), nothing where there is no smoke.
    DensityProfile profile(const Ray& ray, double tmin, double tmax) const;

private:
    // Calls even(t0, t1, density) over the stretches of even smoke (or none) and uneven(t0, t1) over runs of
    // cells of uneven smoke, in order along [tmin, tmax].
    template <class Even, class Uneven>
    void forEachRun(const Ray& ray, double tmin, double tmax, Even&& even, Uneven&& uneven) const;

    SmokeDescription description_;
    double time_;
    MajorantGrid majorant_;
    Bounds3 bounds_;
    double scale_, scaleDown_;  // the largest band of extinctionPerDensity, rounded up and down
    std::shared_ptr<const BlackbodyTable> blackbodies_;  // flames only
    EmissionCells flames_;
};

}  // namespace brume
