#pragma once
#include "material/material.h"

namespace brume {

class NormalMaterial : public Material {
public:
    NormalMaterial(const SceneObject& o, const MaterialSettings& settings);
    bool scatter(const Shading& s, Lobes& lobes) const override;
    Spectrum shadowTransmission(const Shading& s, dvec3& dir) const override;
    bool passesShadows() const override { return kind_ == Kind::Trans && pure(); }

private:
    enum class Kind { Plastic, Metal, Trans };
    bool pure() const;
    double specular(double cosine, double& fresnel) const;

    MaterialSettings settings_;
    Kind kind_;
    Spectrum color_;
    double spec_, alpha2_, trans_ = 0, transSpec_ = 0;
};

}  // namespace brume
