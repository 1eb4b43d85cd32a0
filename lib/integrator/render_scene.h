// The scene compiled for rendering: exact geometry in Embree, the material or emitter of every surface,
// and the light sources for next-event estimation.
#pragma once
#include <memory>
#include <unordered_map>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/light.h"
#include "material/material.h"
#include "pattern/modifier_chain.h"

namespace brume {

// A flat mirror, through which next-event estimation reaches sources by their mirror images (-dr).
struct PlanarMirror {
    int surface;
    dvec3 normal;  // its front
    double offset;  // normal · any point of its plane
    Spectrum reflectance;
};

class RenderScene {
public:
    // Throws Error (file:line) for objects of unknown types, types Brume does not have yet, bad arguments.
    RenderScene(const Scene& scene, const MaterialSettings& settings);

    const Scene& scene() const { return scene_; }
    const SceneGeometry& geometry() const { return *geometry_; }
    const std::vector<Light>& lights() const { return lights_; }

    // The object that shades surface s: a material or an emitter, patterns skipped; -1 when a mixture
    // decides at each hit, or when nothing does (a surface whose modifiers hold no material is invisible).
    int materialObject(int surface) const { return surfaceMaterial_[surface]; }
    // Whether patterns, textures or mixtures modify surface s: then modifiers().resolve(surfaceModifier(s), …)
    // at each hit says what shades it.
    bool varies(int surface) const { return modifiers_->varies(surfaceModifier(surface)); }
    int surfaceModifier(int surface) const { return scene_.objects[geometry_->surfaces()[surface].object].modifier; }
    const ModifierChain& modifiers() const { return *modifiers_; }
    const Material* material(int object) const { return materials_[object].get(); }
    const Emitter* emitter(int object) const { return emitters_[object].get(); }
    // For an antimatter object: the modifiers whose surfaces it cuts away inside its volume (else nullptr).
    const std::vector<int>* clippedModifiers(int object) const {
        auto it = antimatter_.find(object);
        return it == antimatter_.end() ? nullptr : &it->second;
    }
    // The light that samples surface s, or -1.
    int lightOfSurface(int surface) const { return surfaceLight_[surface]; }
    const std::vector<PlanarMirror>& planarMirrors() const { return mirrors_; }
    bool isPlanarMirror(int surface) const { return surfaceMirror_[surface] >= 0; }
    // Distant sources hit by rays that escape the scene (lights, glows and illums on `source`).
    const std::vector<int>& distantLights() const { return distant_; }

private:
    void checkTypes() const;
    void addSources();
    void addAntimatter();
    void addMirrors();

    const Scene& scene_;
    std::unique_ptr<ModifierChain> modifiers_;
    std::vector<std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Emitter>> emitters_;
    std::unique_ptr<SceneGeometry> geometry_;
    std::vector<int> surfaceMaterial_, surfaceLight_;
    std::vector<Light> lights_;
    std::vector<int> distant_;  // indices into lights_
    std::unordered_map<int, std::vector<int>> antimatter_;
    std::vector<PlanarMirror> mirrors_;
    std::vector<int> surfaceMirror_;  // index in mirrors_, or -1
};

}  // namespace brume
