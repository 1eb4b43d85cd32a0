// A Klems BSDF as Radiance's BSDF library and m_bsdf.c use it: each distribution's smallest value is split
// off as a Lambertian part (when it is worth it), the rest is a piecewise-constant "non-diffuse" BSDF,
// evaluated and sampled patch by patch. Directions are in the BSDF's local frame (z along the surface
// normal), both pointing away from the surface: `view` toward where the ray came from, `light` toward the
// light.
//
// Radiance never looks the view direction up as it is: it jitters it over a square of the size of a patch
// (m_bsdf.c's bsdf_jitter, side √(projected solid angle)), which blurs the patch edges of the view. The
// smoothed* functions do the same deterministically, averaging kJitter² stratified views, so that Brume's
// answer is the mean of Radiance's noisy one.
#pragma once
#include <array>
#include <map>
#include <optional>

#include "material/bsdf_xml.h"

namespace brume {

using Rgb = std::array<float, 3>;

class KlemsBsdf {
public:
    explicit KlemsBsdf(KlemsData data);
    // Fixed in place: the totals below are keyed by the addresses of the distributions.
    KlemsBsdf(const KlemsBsdf&) = delete;
    KlemsBsdf& operator=(const KlemsBsdf&) = delete;

    // Lambertian reflectance and transmittance (hemispherical, not divided by π) for light arriving on the
    // front or the back.
    Rgb diffuseReflection(bool front) const { return front ? reflectLamb_[0] : reflectLamb_[1]; }
    Rgb diffuseTransmission(bool front) const { return front ? transmitLamb_[0] : transmitLamb_[1]; }
    bool transmits() const { return transmitFront_ || transmitBack_; }

    // The non-diffuse BSDF (1/sr) between the two directions.
    Rgb value(const dvec3& view, const dvec3& light) const;
    // The CIE Y of the non-diffuse part scattered into the view's own side (reflection) or the other one,
    // for this view direction (Radiance's SDdirectHemi).
    double albedo(const dvec3& view, bool transmit) const;
    // A light direction on that side, drawn with density pdf(): nothing if there is nothing to draw.
    std::optional<dvec3> sample(const dvec3& view, bool transmit, double u, double v) const;
    // The density per projected solid angle (sr⁻¹) with which sample(view, side of light) draws light.
    double projectedPdf(const dvec3& view, const dvec3& light) const;

    // The same with the view jittered as Radiance does: for direct light over the smaller of the view's and
    // the light's patches (direct_specular_OK), for sampled rays and -st over the view's (sample_sdf).
    static constexpr int kJitter = 4;
    Rgb smoothedValue(const dvec3& view, const dvec3& light) const;
    double smoothedAlbedo(const dvec3& view, bool transmit) const;
    // Picks a jittered view by its albedo, then a direction for it: the weight f·cos/pdf of a draw is
    // smoothedAlbedo() when the light's patch is no smaller than the view's.
    std::optional<dvec3> smoothedSample(const dvec3& view, bool transmit, double u, double v) const;
    double smoothedProjectedPdf(const dvec3& view, const dvec3& light) const;

private:
    using Views = std::array<dvec3, kJitter * kJitter>;
    // The projected solid angle of the view's patch in the distribution toward `light`'s side (0: none).
    double viewPatch(const dvec3& view, bool transmit) const;
    double lightPatch(const dvec3& view, const dvec3& light) const;
    static Views jittered(const dvec3& view, double side);
    template <class F>
    void forEachView(const Views& views, const dvec3& light, F f) const;
    // One column (or, by reciprocity, one row) of a matrix: the distribution for one view patch.
    struct Slice;
    const KlemsMatrix* matrix(bool viewFront, bool lightFront) const;
    std::optional<Slice> slice(const dvec3& view, bool transmit) const;
    void splitDiffuse(std::optional<KlemsMatrix>& m, Rgb& lambertian);

    std::optional<KlemsMatrix> reflectFront_, reflectBack_, transmitFront_, transmitBack_;
    // Per distribution: the hemispherical sum of each column (incident patch) and row (outgoing patch).
    std::map<const KlemsMatrix*, std::vector<double>> columnTotals_, rowTotals_;
    std::vector<std::unique_ptr<KlemsBasis>> ownBases_;
    Rgb reflectLamb_[2]{}, transmitLamb_[2]{};
};

// Radiance's brightness of an RGB value (its CIE Y).
inline double luminance(const Rgb& c) { return 0.265106 * c[0] + 0.670106 * c[1] + 0.064788 * c[2]; }

}  // namespace brume
