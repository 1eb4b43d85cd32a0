// Materials with only specular (Dirac) lobes: mirror, glass, dielectric.
#pragma once
#include "material/material.h"

namespace brume {

// mirror: R G B reflectance (reference manual §"Mirror"). Black from behind, or invisible with -bv-.
class Mirror : public Material {
public:
    Mirror(const SceneObject& o, const MaterialSettings& settings);
    bool scatter(const Shading& s, Lobes& lobes) const override;

private:
    Spectrum color_;
    bool backVisible_;
};

// glass: thin glass with multiple internal reflections; R G B are transmissivities at normal incidence,
// optional refractive index (default 1.52). Rays go straight through (reference manual §"Glass").
class Glass : public Material {
public:
    Glass(const SceneObject& o, const MaterialSettings& settings);
    bool scatter(const Shading& s, Lobes& lobes) const override;
    Spectrum shadowTransmission(const Shading& s, dvec3& dir) const override;
    bool passesShadows() const override { return true; }

private:
    void coefficients(double cosine, Spectrum& reflect, Spectrum& transmit) const;
    Spectrum color_;
    double index_;
    bool backVisible_;
};

// dielectric: a refracting boundary with Fresnel reflection; R G B are transmission per unit length
// inside, index n + hartmann/500 (reference manual §"Dielectric").
class Dielectric : public Material {
public:
    explicit Dielectric(const SceneObject& o);
    bool scatter(const Shading& s, Lobes& lobes) const override;
    Spectrum shadowTransmission(const Shading& s, dvec3& dir) const override;
    bool passesShadows() const override { return true; }

private:
    // Fresnel reflectance and refracted direction (refracted is false on total internal reflection).
    double fresnel(const Shading& s, dvec3& refractedDir, double& ratio, bool& refracted) const;
    Spectrum color_;
    double index_;
};

}  // namespace brume
