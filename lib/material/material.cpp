#include "material/material.h"

#include "material/anisotropic.h"
#include "material/bsdf_material.h"
#include "material/function_brdf.h"
#include "material/normal.h"
#include "material/specular.h"

namespace brume {

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
