#include "material/material.h"

#include <set>

#include "material/anisotropic.h"
#include "material/bsdf_material.h"
#include "material/function_brdf.h"
#include "material/normal.h"
#include "material/specular.h"

namespace brume {

bool isMaterialType(const std::string& t) {
    static const std::set<std::string> kTypes{"plastic", "metal",  "trans",  "mirror",
                                              "glass",   "dielectric", "plastic2", "metal2", "trans2", "BSDF"};
    return kTypes.count(t) > 0 || isFunctionBrdfType(t);
}

bool isEmitterType(const std::string& t) { return t == "light" || t == "spotlight" || t == "glow" || t == "illum"; }

std::vector<std::unique_ptr<Material>> makeMaterials(const Scene& scene, const MaterialSettings& settings,
                                                     PatternLibrary& functions) {
    std::vector<std::unique_ptr<Material>> materials(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.type == "plastic" || o.type == "metal" || o.type == "trans")
            materials[i] = std::make_unique<NormalMaterial>(o, settings);
        else if (o.type == "mirror") materials[i] = std::make_unique<Mirror>(o, settings);
        else if (o.type == "glass") materials[i] = std::make_unique<Glass>(o, settings);
        else if (o.type == "dielectric") materials[i] = std::make_unique<Dielectric>(o);
        else if (o.type == "BSDF") materials[i] = std::make_unique<BsdfMaterial>(o, settings);
        else if (o.type == "plastic2" || o.type == "metal2" || o.type == "trans2")
            materials[i] = std::make_unique<AnisotropicMaterial>(o, settings, functions);
        else if (isFunctionBrdfType(o.type))
            materials[i] = std::make_unique<FunctionBrdfMaterial>(o, settings, functions);
    }
    return materials;
}

}  // namespace brume
