#include "integrator/render_scene.h"

#include <numbers>
#include <set>

namespace brume {

namespace {

// Types of Radiance 6.1 that later work will add; a scene using them gets a clear error, not a wrong picture.
const std::set<std::string> kPlannedTypes{
    "mesh", "instance", "mist", "spectrum", "specfile",
    "specfunc", "specdata", "specpict", "plastic2", "metal2", "trans2", "ashik2", "WGMDfunc", "interface",
    "prism1", "prism2", "BSDF", "aBSDF", "plasfunc", "metfunc", "transfunc", "plasdata", "metdata", "transdata",
    "BRTDfunc"};

}  // namespace

RenderScene::RenderScene(const Scene& scene, const MaterialSettings& settings) : scene_(scene) {
    checkTypes();
    modifiers_ = std::make_unique<ModifierChain>(scene);
    addAntimatter();
    materials_ = makeMaterials(scene, settings);
    emitters_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (isEmitterType(scene.objects[i].type))
            emitters_[i] = std::make_unique<Emitter>(makeEmitter(scene, scene.objects[i]));

    std::vector<Surface> surfaces;
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        const SceneObject& o = scene.objects[i];
        if (!isSurfaceType(o.type)) continue;
        if (o.modifier < 0) continue;  // a void surface is never seen (Radiance drops it too)
        auto surface = makeSurface(scene, i);
        if (!surface) continue;
        if (!withinTraceableRange(surface->shape)) {
            warn(o.where.str() + ": " + o.type + " \"" + o.name + "\" reaches beyond ±1e18, where rays cannot be traced; dropped");
            continue;
        }
        surfaces.push_back(std::move(*surface));
        surfaceMaterial_.push_back(modifiers_->fixedMaterial(o.modifier));
    }
    geometry_ = std::make_unique<SceneGeometry>(std::move(surfaces));
    addSources();
    addMirrors();
}

void RenderScene::checkTypes() const {
    for (const SceneObject& o : scene_.objects) {
        if (isSurfaceType(o.type) || isMaterialType(o.type) || isEmitterType(o.type) || o.type == "source" ||
            o.type == "antimatter" || isPatternType(o.type) || isMixtureType(o.type))
            continue;
        if (kPlannedTypes.count(o.type))
            throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
        throw Error(o.where, "unknown object type '" + o.type + "' (" + o.name + ")");
    }
    for (const SceneObject& o : scene_.objects) {
        if (o.modifier < 0) continue;
        const SceneObject& m = scene_.objects[o.modifier];
        if (!isMaterialType(m.type) && !isEmitterType(m.type) && m.type != "antimatter" && !isPatternType(m.type) &&
            !isMixtureType(m.type))
            throw Error(o.where, "modifier '" + m.name + "' of " + o.type + " \"" + o.name + "\" is a " + m.type +
                                     ", not a material, pattern, texture or mixture");
    }
}

// antimatter: N strings naming the modifiers it cuts (Radiance reference manual, "Antimatter").
void RenderScene::addAntimatter() {
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (o.type != "antimatter") continue;
        if (o.strings.empty() || !o.integers.empty() || !o.reals.empty())
            throw Error(o.where, "bad arguments for antimatter \"" + o.name + "\": expected modifier names only");
        std::vector<int>& cut = antimatter_[i];
        for (const std::string& name : o.strings) {
            if (name == "void") continue;
            auto it = scene_.lastDefinition.find(name);
            if (it == scene_.lastDefinition.end())
                throw Error(o.where, "undefined modifier \"" + name + "\" in antimatter \"" + o.name + "\"");
            cut.push_back(it->second);
        }
    }
}

void RenderScene::addMirrors() {
    const auto& surfaces = geometry_->surfaces();
    surfaceMirror_.assign(surfaces.size(), -1);
    for (int s = 0; s < static_cast<int>(surfaces.size()); ++s) {
        // A patterned mirror varies over its surface: rays, not virtual sources, find what it reflects.
        if (surfaceMaterial_[s] < 0 || varies(s)) continue;
        const SceneObject& m = scene_.objects[surfaceMaterial_[s]];
        if (m.type != "mirror") continue;
        Spectrum rho(float(m.reals[0]), float(m.reals[1]), float(m.reals[2]));
        if (const auto* poly = std::get_if<Polygon>(&surfaces[s].shape)) {
            surfaceMirror_[s] = int(mirrors_.size());
            mirrors_.push_back({s, poly->normal, poly->planeOffset, rho});
        } else if (const auto* ring = std::get_if<Ring>(&surfaces[s].shape)) {
            surfaceMirror_[s] = int(mirrors_.size());
            mirrors_.push_back({s, ring->normal, glm::dot(ring->normal, ring->center), rho});
        }
    }
}

void RenderScene::addSources() {
    const auto& surfaces = geometry_->surfaces();
    surfaceLight_.assign(surfaces.size(), -1);
    for (int s = 0; s < static_cast<int>(surfaces.size()); ++s) {
        const Emitter* e = surfaceMaterial_[s] >= 0 ? emitters_[surfaceMaterial_[s]].get() : nullptr;
        if (!e || !e->isDirectSource() || e->radiance.maxValue() <= 1e-6f) continue;
        const SceneObject& o = scene_.objects[surfaces[s].object];
        const auto* cone = std::get_if<Cone>(&surfaces[s].shape);
        const auto* sphere = std::get_if<Sphere>(&surfaces[s].shape);
        if ((cone && (cone->inward || cone->baseRadius != cone->topRadius)) || (sphere && sphere->inward))
            throw Error(o.where, "illegal source shape " + o.type + " \"" + o.name +
                                     "\": light sources are polygons, rings, spheres, cylinders or sources");
        surfaceLight_[s] = static_cast<int>(lights_.size());
        lights_.emplace_back(surfaces[s], s, e, varies(s));
    }
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (o.type != "source" || o.modifier < 0) continue;
        if (!o.strings.empty() || !o.integers.empty() || o.reals.size() != 4)
            throw Error(o.where, "bad arguments for source \"" + o.name + "\": expected 4 reals");
        int material = modifiers_->fixedMaterial(o.modifier);
        const Emitter* e = material >= 0 ? emitters_[material].get() : nullptr;
        if (!e) throw Error(o.where, "source \"" + o.name + "\" needs a light, glow, illum or spotlight modifier");
        dvec3 dir(o.reals[0], o.reals[1], o.reals[2]);
        double angle = o.reals[3] * std::numbers::pi / 180;
        if (!(glm::length(dir) > 0) || !(angle > 0))
            throw Error(o.where, "bad direction or angle for source \"" + o.name + "\"");
        distant_.push_back(static_cast<int>(lights_.size()));
        lights_.emplace_back(dir, angle, e, i, modifiers_->varies(o.modifier));
    }
}

}  // namespace brume
