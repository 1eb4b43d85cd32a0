// Radiance's BSDF material (reference manual §"BSDF"; semantics of its rt/m_bsdf.c) for Klems data:
//   mod BSDF id  6+ thick BSDFfile ux uy uz funcfile [transform]  0  0|3|6|9 [front rgb] [back rgb] [trans rgb]
// The file's Lambertian parts plus the extra diffuse arguments are the diffuse lobes (to direct light and
// the ambient calculation); the rest is a general lobe: direct light always, sampled rays when its
// directional-hemispherical part exceeds -st on that side, else added to the ambient coefficient.
#pragma once
#include <glm/geometric.hpp>

#include "material/bsdf_klems.h"
#include "material/material.h"

namespace brume {

class BsdfMaterial : public Material {
public:
    BsdfMaterial(const SceneObject& o, const MaterialSettings& settings);
    bool scatter(const Shading& s, Lobes& lobes) const override;
    // Shadow rays stop here, as in Radiance (thin BSDF surfaces pass no shadow rays): light from sources
    // through the surface is its general lobe's, found where rays meet it.

private:
    // The local frame at a hit: z along the surface normal as the surface faces (not turned toward the
    // ray), y along the up vector's part across it.
    struct Frame {
        dvec3 x, y, z;
        dvec3 toLocal(const dvec3& d) const { return {glm::dot(d, x), glm::dot(d, y), glm::dot(d, z)}; }
        dvec3 toWorld(const dvec3& d) const { return d.x * x + d.y * y + d.z * z; }
    };
    // What the general lobe needs at a hit, recomputed from the Shading on each call.
    struct View {
        Frame frame;
        dvec3 view;  // local, toward where the ray came from
    };
    struct Split {
        double albedo[2];  // non-diffuse CIE Y, reflected and transmitted
        bool sampled[2];   // above -st: traced by sampled rays
        double share(bool transmit) const;  // the chance sample() draws that side
    };
    class Lobe : public GeneralLobe {
    public:
        explicit Lobe(const BsdfMaterial& m) : m_(m) {}
        Spectrum response(const Shading& s, const dvec3& wi) const override;
        double pdf(const Shading& s, const dvec3& wi) const override;
        std::optional<LobeSample> sample(const Shading& s, double u, double v) const override;

    private:
        const BsdfMaterial& m_;
    };

    std::optional<Frame> frameAt(const Shading& s) const;
    std::optional<View> viewAt(const Shading& s) const;
    Split split(const View& v) const;
    Spectrum response(const Shading& s, const View& v, const dvec3& light) const;
    void readDiffuse(const SceneObject& o);

    MaterialSettings settings_;
    std::string name_;
    uint64_t id_;  // unique over the process, unlike addresses: keys the per-thread cache of split()
    KlemsBsdf bsdf_;
    dvec3 up_;
    Rgb extraReflect_[2]{}, extraTransmit_{};  // the real arguments: front, back reflection; transmission
    Lobe lobe_{*this};
};

}  // namespace brume
