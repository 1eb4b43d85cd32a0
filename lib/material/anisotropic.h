// plastic2, metal2 and trans2: Radiance's anisotropic materials (reference manual §"Plastic2", "Metal2",
// "Trans2"; the split of reflectances, the -st semantics and the orientation rules follow its aniso.c).
// String arguments ux uy uz funcfile [transform]: the lobe's u direction, by .cal expressions at the hit.
#pragma once
#include <atomic>

#include "material/aniso_ward.h"
#include "material/material.h"
#include "pattern/function_object.h"

namespace brume {

class AnisotropicMaterial : public Material, private GeneralLobe {
public:
    AnisotropicMaterial(const SceneObject& o, const MaterialSettings& settings, PatternLibrary& functions);
    bool scatter(const Shading& s, Lobes& lobes) const override;

private:
    // The lobe's specular parts at one hit: colours, frame, and which parts sampled rays trace (above -st).
    struct At {
        AnisoFrame frame;
        Spectrum reflect, transmit;
        double reflectShare = 0, transmitShare = 0;  // of the sampled draws
    };
    At at(const Shading& s) const;
    AnisoFrame frame(const Shading& s) const;
    Spectrum response(const Shading& s, const dvec3& wi) const override;
    double pdf(const Shading& s, const dvec3& wi) const override;
    std::optional<LobeSample> sample(const Shading& s, double x, double y) const override;
    Spectrum response(const Shading& s, const At& a, const dvec3& wi) const;
    double pdf(const Shading& s, const At& a, const dvec3& wi) const;

    MaterialSettings settings_;
    bool metal_;
    std::string where_;  // for the warning about the orientation
    Spectrum color_;
    double spec_, au2_, av2_, trans_ = 0, tspec_ = 0;
    FunctionObject orientation_;  // ux uy uz
};

}  // namespace brume
