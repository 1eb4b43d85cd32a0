// plasfunc, metfunc, transfunc, plasdata, metdata and transdata: Radiance's materials whose specular part
// is a function of the light direction (reference manual §"Plasfunc" … "Transdata"; the semantics follow its
// m_brdf.c). As in Radiance the function gives that part's light from the sources only: for indirect light
// the specular reflectance (transmittance) joins the diffuse one as the ambient coefficient.
#pragma once
#include "material/material.h"
#include "pattern/data_grid.h"
#include "pattern/function_object.h"

namespace brume {

class FunctionBrdfMaterial : public Material, private GeneralLobe {
public:
    FunctionBrdfMaterial(const SceneObject& o, const MaterialSettings& settings, PatternLibrary& functions);
    bool scatter(const Shading& s, Lobes& lobes) const override;

private:
    Spectrum response(const Shading& s, const dvec3& wi) const override;
    double pdf(const Shading&, const dvec3&) const override { return 0; }  // never sampled
    std::optional<LobeSample> sample(const Shading&, double, double) const override { return std::nullopt; }
    // The function's value for light from world direction wi.
    double value(const Shading& s, const dvec3& wi) const;

    bool backVisible_;
    bool metal_, transmits_;
    Spectrum color_;
    double rspec_, trans_ = 0, tspec_ = 0;
    FunctionObject f_;
    cal::FuncId brdf_;  // of (lx, ly, lz, Ω), or for data types (value, lx, ly, lz, Ω)
    const DataGrid* data_ = nullptr;
    std::vector<cal::FuncId> coordinates_;  // data types: each of (lx, ly, lz, Ω)
};

}  // namespace brume
