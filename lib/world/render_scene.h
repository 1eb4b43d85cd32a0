// The scene compiled for rendering: exact geometry in Embree, the material or emitter of every surface,
// and the light sources for next-event estimation.
#pragma once
#include <algorithm>
#include <deque>
#include <memory>
#include <unordered_map>
#include <vector>

#include "world/scene_geometry.h"
#include "light/light.h"
#include "light/portal.h"
#include "material/material.h"
#include "medium/mist.h"
#include "medium/smoke.h"
#include "pattern/modifier_chain.h"

namespace brume {

// A flat mirror, through which next-event estimation reaches sources by their mirror images (-dr).
struct PlanarMirror {
    SurfaceId surface;
    dvec3 normal;  // its front
    double offset;  // normal · any point of its plane
    Spectrum reflectance;
};

class RenderScene : public ShadowBlockers {
public:
    // Throws Error (file:line) for objects of unknown types, types Brume does not have yet, bad arguments.
    RenderScene(const Scene& scene, const MaterialSettings& settings);

    const Scene& scene() const { return scene_; }
    const SceneGeometry& geometry() const { return *geometry_; }
    const std::vector<Light>& lights() const { return lights_; }

    // The modifier a surface's chain starts from: its own, or that of the instance or mesh placing it (see
    // Placement::modifierObject), or a mesh triangle's material.
    int surfaceModifier(const SurfaceId& id) const;
    // The object that shades a surface: a material or an emitter, patterns skipped; -1 when a mixture decides
    // at each hit, or when nothing does (a surface whose modifiers hold no material is invisible).
    int materialObject(const SurfaceId& id) const { return modifiers_->fixedMaterial(surfaceModifier(id)); }
    // Whether patterns, textures or mixtures modify a surface: then modifiers().resolve(surfaceModifier(id), …)
    // at each hit says what shades it.
    bool varies(const SurfaceId& id) const { return modifiers_->varies(surfaceModifier(id)); }
    const ModifierChain& modifiers() const { return *modifiers_; }
    // The modifier a light's chain starts from: its surface's (see surfaceModifier), or a source's at infinity.
    int lightModifier(const Light& light) const {
        return light.isDistant() ? scene_.objects[light.object()].modifier : surfaceModifier(light.surface());
    }
    // The frame of the instance or mesh a surface is placed by, as patterns see it (Radiance's object
    // transform); nullptr for the scene's own surfaces.
    const ObjectFrame* objectFrame(const SurfaceId& id) const {
        return id.instance < 0 ? nullptr : &objectFrames_[id.instance];
    }
    // The object rtrace names for a surface (-os): the surface, or the instance or mesh whose modifier it
    // takes, or the mesh of a triangle.
    int surfaceObject(const SurfaceId& id) const;
    const Material* material(int object) const { return materials_[object].get(); }
    const Emitter* emitter(int object) const { return emitters_[object].get(); }
    // For an antimatter object: the modifiers whose surfaces it cuts away inside its volume (else nullptr).
    const std::vector<int>* clippedModifiers(int object) const {
        auto it = antimatter_.find(object);
        return it == antimatter_.end() ? nullptr : &it->second;
    }
    // For a mist object: what it does to the medium of rays crossing it (else nullptr).
    const Mist* mist(int object) const {
        auto it = mists_.find(object);
        return it == mists_.end() ? nullptr : &it->second;
    }
    bool hasMists() const { return !mists_.empty(); }
    // The scene's smoke objects, their extinction times their spectrum modifier.
    const std::vector<SmokeDescription>& smoke() const { return smoke_; }
    // Whether the scene looks different at different instants (-T): smoke with several key frames.
    bool variesInTime() const {
        return std::any_of(smoke_.begin(), smoke_.end(), [](const SmokeDescription& s) { return s.frames->keyFrames().size() > 1; });
    }
    // The light that samples a surface, or -1.
    int lightOfSurface(const SurfaceId& id) const;
    const std::vector<PlanarMirror>& planarMirrors() const { return mirrors_; }
    // Flat mirrors of the scene's own (as in Radiance, those of instances relay no source images).
    bool isPlanarMirror(const SurfaceId& id) const {
        return id.instance < 0 && id.surface >= 0 && surfaceMirror_[id.surface] >= 0;
    }
    // Surfaces that stop every shadow ray they meet: a fixed material that never transmits (or a source other
    // than an illum), never cut away by antimatter.
    bool blocksShadows(const SurfaceId& id) const override {
        int modifier = surfaceModifier(id);
        return modifier >= 0 && blocksShadows_[modifier];
    }
    // Whether a blocking surface met anywhere on a shadow ray (in whatever order Embree finds it) decides it:
    // no surface can bend a shadow ray away from it (dielectric), nor draw random numbers where a shadow ray
    // crosses it before (patterned or mixed surfaces), which would change the samples that follow.
    bool blockersDecide() const override { return blockersDecide_; }
    // Whether shadow rays may change direction where they cross a surface (dielectrics refract them).
    bool shadowsBend() const { return shadowsBend_; }
    // Distant sources hit by rays that escape the scene (lights, glows and illums on `source`).
    const std::vector<int>& distantLights() const { return distant_; }
    // Clear glazing (flat `glass` of the scene's own) through which the sky or ground glows can be seen:
    // windows for next-event estimation of the sky (none when there is no glow at infinity).
    const std::vector<Portal>& portals() const { return portals_; }

private:
    void checkTypes() const;
    void addSources();
    void addSurfaceLight(const Surface& surface, const SurfaceId& id);
    void addPlacedLights();
    void addAntimatter();
    void addMirrors();
    void addPortals();
    bool leadsOutside(const Polygon& pane, const SurfaceId& id, const std::vector<bool>& glazing) const;
    void addMists();
    void addSmoke();
    void findShadowBlockers();
    bool anyVaryingSurface() const;

    const Scene& scene_;
    std::unique_ptr<ModifierChain> modifiers_;
    std::vector<std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Emitter>> emitters_;
    std::unique_ptr<SceneGeometry> geometry_;
    std::vector<int> surfaceModifier_, surfaceLight_;  // per surface of the geometry (own: surfaceLight_ only)
    // Sources of instanced octrees, per placement: their surfaces moved into the world, and their lights.
    std::deque<Surface> placedLightSurfaces_;
    std::unordered_map<uint64_t, int> placedLight_;  // (placement, surface) → light
    std::vector<ObjectFrame> objectFrames_;  // per placement
    std::vector<Light> lights_;
    std::vector<int> distant_;  // indices into lights_
    std::unordered_map<int, std::vector<int>> antimatter_;
    std::vector<PlanarMirror> mirrors_;
    std::vector<Portal> portals_;
    std::unordered_map<int, Mist> mists_;
    std::vector<SmokeDescription> smoke_;
    std::vector<int> surfaceMirror_;  // index in mirrors_, or -1
    std::vector<bool> blocksShadows_;  // per modifier object
    bool blockersDecide_ = true;
    bool shadowsBend_ = false;
};

}  // namespace brume
