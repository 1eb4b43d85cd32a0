#include "world/render_scene.h"

#include <algorithm>
#include <numbers>
#include <set>

#include "pattern/pattern_evaluator.h"
#include "sampling/warp.h"

namespace brume {

namespace {

// Types of Radiance 6.1 that later work will add; a scene using them gets a clear error, not a wrong picture.
const std::set<std::string> kPlannedTypes{
    "spectrum", "specfile", "specfunc", "specdata", "specpict", "ashik2",
    "WGMDfunc", "interface", "prism1", "prism2", "aBSDF", "BRTDfunc"};

// The key of a placed surface in RenderScene::placedLight_.
uint64_t placedKey(int placement, int surface) { return uint64_t(uint32_t(placement)) << 32 | uint32_t(surface); }

}  // namespace

RenderScene::RenderScene(const Scene& scene, const MaterialSettings& settings) : scene_(scene) {
    checkTypes();
    modifiers_ = std::make_unique<ModifierChain>(
        scene, [&](PatternLibrary& functions) { materials_ = makeMaterials(scene, settings, functions); });
    addAntimatter();
    emitters_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (isEmitterType(scene.objects[i].type)) emitters_[i] = std::make_unique<Emitter>(makeEmitter(scene, int(i)));
    geometry_ = std::make_unique<SceneGeometry>(layoutScene(scene));
    for (const Surface& s : geometry_->surfaces()) surfaceModifier_.push_back(scene.objects[s.object].modifier);
    for (const Placement& p : geometry_->placements())
        objectFrames_.push_back({p.patternTransform, p.patternTransform.inverse()});
    addSources();
    addMirrors();
    addPortals();
    addMists();
    addSmoke();
    findShadowBlockers();
}

// Which modifiers make their surfaces stop shadow rays, as the shadow-ray walk (ShadowRays::toSurface)
// judges them: not patterned, mixed or cut away, and neither passing light (glass, trans, dielectric, void
// materials) nor an illum, whose effect depends on the source behind it.
void RenderScene::findShadowBlockers() {
    std::vector<bool> cutAway(scene_.objects.size(), false);
    for (const auto& [antimatter, cut] : antimatter_)
        for (int modifier : cut) cutAway[modifier] = true;
    blocksShadows_.assign(scene_.objects.size(), false);
    for (int i = 0; i < int(scene_.objects.size()); ++i) {
        shadowsBend_ = shadowsBend_ || scene_.objects[i].type == "dielectric";
        int material = modifiers_->fixedMaterial(i);
        if (modifiers_->varies(i) || material < 0 || cutAway[material] || clippedModifiers(material)) continue;
        if (const Emitter* e = emitters_[material].get())
            blocksShadows_[i] = e->kind != Emitter::Kind::Illum;
        else
            blocksShadows_[i] = materials_[material] && !materials_[material]->passesShadows();
    }
    blockersDecide_ = !shadowsBend_ && !anyVaryingSurface();
}

// Whether patterns or mixtures modify any surface a ray can meet (those on sources at infinity, skies, it
// never meets): surfaces, instances and meshes, and the triangles of meshes.
bool RenderScene::anyVaryingSurface() const {
    for (const SceneObject& o : scene_.objects)
        if ((isSurfaceType(o.type) || o.type == "instance" || o.type == "mesh") && modifiers_->varies(o.modifier))
            return true;
    for (const Prototype& p : geometry_->prototypes())
        if (p.mesh && std::any_of(p.mesh->materials.begin(), p.mesh->materials.end(),
                                  [&](int m) { return modifiers_->varies(m); }))
            return true;
    return false;
}

void RenderScene::checkTypes() const {
    for (const SceneObject& o : scene_.objects) {
        if (isSurfaceType(o.type) || isMaterialType(o.type) || isEmitterType(o.type) || o.type == "source" ||
            o.type == "antimatter" || o.type == "mist" || o.type == "smoke" ||
            o.type == "instance" || o.type == "mesh" || isPatternType(o.type) ||
            isMixtureType(o.type))
            continue;
        if (kPlannedTypes.count(o.type))
            throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
        throw Error(o.where, "unknown object type '" + o.type + "' (" + o.name + ")");
    }
    for (const SceneObject& o : scene_.objects) {
        if (o.modifier < 0) continue;
        const SceneObject& m = scene_.objects[o.modifier];
        if (!isMaterialType(m.type) && !isEmitterType(m.type) && m.type != "antimatter" && m.type != "mist" &&
            !isPatternType(m.type) &&
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
            int modifier = scene_.modifierBefore(i, name);
            if (modifier < 0)
                throw Error(o.where, "undefined modifier \"" + name + "\" in antimatter \"" + o.name + "\"");
            cut.push_back(modifier);
        }
    }
}

// Mists; a pattern on one would scale its extinction (Radiance's line integrals), which Brume does not do.
void RenderScene::addMists() {
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (o.type != "mist") continue;
        if (o.modifier >= 0)
            throw Error(o.where, "patterns on mist \"" + o.name + "\" are not supported by Brume yet");
        Mist& mist = mists_[i] = readMist(o);
        for (const std::string& name : mist.sources) {
            std::string source = name.substr(name.rfind('>') + 1);  // Radiance's relays: mirror>source
            bool known = std::any_of(lights_.begin(), lights_.end(),
                                     [&](const Light& l) { return scene_.objects[l.object()].name == source; });
            if (!known) warn(o.where.str() + ": unknown source \"" + name +
                             "\" in mist \"" + o.name + "\"");
        }
    }
}

// Smoke; a spectrum as its modifier (spectrum, specfile, specfunc) makes its extinction spectral: K(λ) = K·s(λ).
void RenderScene::addSmoke() {
    for (const SceneObject& o : scene_.objects) {
        if (o.type != "smoke") continue;
        const SceneObject* m = o.modifier >= 0 ? &scene_.objects[o.modifier] : nullptr;
        if (m && m->type != "spectrum" && m->type != "specfile" && m->type != "specfunc")
            throw Error(o.where, "modifier '" + m->name + "' of smoke '" + o.name + "' is a " + m->type +
                                     ": expected a spectrum, specfile or specfunc");
        SmokeDescription smoke = readSmoke(o);
        if (m && smoke.extinctionAt633)
            throw Error(o.where, "smoke '" + o.name + "' has extinction=soot and a spectrum, '" + m->name +
                                     "', as its modifier: one spectral extinction or the other");
        if (m) {
            PatternEvaluator evaluator(*modifiers_);
            PatternHit origin{dvec3(0), dvec3(0, 0, 1), dvec3(0, 0, 1)};
            smoke.extinctionPerDensity *= modifiers_->resolve(o.modifier, origin, evaluator, 0.5).texturing.color;
        }
        smoke_.push_back(std::move(smoke));
    }
}

void RenderScene::addMirrors() {
    const auto& surfaces = geometry_->surfaces();
    surfaceMirror_.assign(surfaces.size(), -1);
    for (int s = 0; s < geometry_->ownSurfaces(); ++s) {
        // A patterned mirror varies over its surface: rays, not virtual sources, find what it reflects.
        int material = materialObject(SurfaceId{s});
        if (material < 0 || varies(SurfaceId{s})) continue;
        const SceneObject& m = scene_.objects[material];
        if (m.type != "mirror") continue;
        Spectrum rho(float(m.reals[0]), float(m.reals[1]), float(m.reals[2]));
        if (const auto* poly = std::get_if<Polygon>(&surfaces[s].shape)) {
            surfaceMirror_[s] = int(mirrors_.size());
            mirrors_.push_back({SurfaceId{s}, poly->normal, poly->planeOffset, rho});
        } else if (const auto* ring = std::get_if<Ring>(&surfaces[s].shape)) {
            surfaceMirror_[s] = int(mirrors_.size());
            mirrors_.push_back({SurfaceId{s}, ring->normal, glm::dot(ring->normal, ring->center), rho});
        }
    }
}

void RenderScene::addPortals() {
    bool sky = std::any_of(distant_.begin(), distant_.end(), [&](int i) {
        const Emitter& e = lights_[i].emitter();
        return e.kind == Emitter::Kind::Glow && !e.radiance.isBlack();
    });
    if (!sky) return;
    const auto& surfaces = geometry_->surfaces();
    std::vector<bool> glazing(surfaces.size(), false);
    for (int s = 0; s < geometry_->ownSurfaces(); ++s) {
        int material = materialObject(SurfaceId{s});
        glazing[s] = material >= 0 && !varies(SurfaceId{s}) && scene_.objects[material].type == "glass" &&
                     std::holds_alternative<Polygon>(surfaces[s].shape);
    }
    for (int s = 0; s < geometry_->ownSurfaces(); ++s)
        if (glazing[s] && leadsOutside(std::get<Polygon>(surfaces[s].shape), SurfaceId{s}, glazing))
            portals_.emplace_back(std::get<Polygon>(surfaces[s].shape), SurfaceId{s});
}

// Whether rays from a pane's middle, straight out of either face or slanted 60° from it, escape the scene
// through nothing but glazing: then it is a window, not a glass partition or a glass table top (which would
// only waste the sky's samples; either way the estimate stays unbiased).
bool RenderScene::leadsOutside(const Polygon& pane, const SurfaceId& id, const std::vector<bool>& glazing) const {
    const auto& tri = pane.triangles.front();
    dvec3 middle = (pane.vertices[tri[0]] + pane.vertices[tri[1]] + pane.vertices[tri[2]]) / 3.0;
    constexpr int kSlants = 8;
    for (double side : {1.0, -1.0}) {
        Frame frame(side * pane.normal);
        for (int k = 0; k <= kSlants; ++k) {
            double phi = 2 * std::numbers::pi * k / kSlants, sinTheta = k == 0 ? 0 : std::sqrt(0.75);
            dvec3 dir = frame.toWorld(dvec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), k == 0 ? 1 : 0.5));
            Ray ray(middle, dir, std::numeric_limits<double>::infinity(), id);
            for (int crossing = 0; crossing < 16; ++crossing) {
                auto hit = geometry_->intersect(ray);
                if (!hit) return true;
                const SurfaceId& met = hit->surface;
                if (met.instance >= 0 || met.surface < 0 || !glazing[met.surface]) break;
                ray.org = hit->point;
                ray.leaving = met;
            }
        }
    }
    return false;
}

int RenderScene::surfaceModifier(const SurfaceId& id) const {
    if (id.instance >= 0) {
        const Placement& p = geometry_->placements()[id.instance];
        if (p.modifierObject >= 0) return scene_.objects[p.modifierObject].modifier;
        if (id.triangle >= 0) return geometry_->meshOf(id)->materials[id.triangle];
    }
    return surfaceModifier_[id.surface];
}

int RenderScene::surfaceObject(const SurfaceId& id) const {
    if (id.instance >= 0) {
        const Placement& p = geometry_->placements()[id.instance];
        if (p.modifierObject >= 0) return p.modifierObject;
        if (id.triangle >= 0) return p.object;
    }
    return geometry_->surfaces()[id.surface].object;
}

int RenderScene::lightOfSurface(const SurfaceId& id) const {
    if (id.triangle >= 0) return -1;
    if (id.instance < 0) return surfaceLight_[id.surface];
    auto it = placedLight_.find(placedKey(id.instance, id.surface));
    return it == placedLight_.end() ? -1 : it->second;
}

// An emitting surface (in world coordinates) becomes a light source, if its emitter makes it one.
void RenderScene::addSurfaceLight(const Surface& surface, const SurfaceId& id) {
    int material = materialObject(id);
    const Emitter* e = material >= 0 ? emitters_[material].get() : nullptr;
    if (!e || !e->isDirectSource() || e->radiance.maxValue() <= 1e-6f) return;
    const SceneObject& o = scene_.objects[surface.object];
    const auto* cone = std::get_if<Cone>(&surface.shape);
    const auto* sphere = std::get_if<Sphere>(&surface.shape);
    if ((cone && (cone->inward || cone->baseRadius != cone->topRadius)) || (sphere && sphere->inward))
        throw Error(o.where, "illegal source shape " + o.type + " \"" + o.name +
                                 "\": light sources are polygons, rings, spheres, cylinders or sources");
    int light = static_cast<int>(lights_.size());
    if (id.instance < 0)
        surfaceLight_[id.surface] = light;
    else
        placedLight_[placedKey(id.instance, id.surface)] = light;
    lights_.emplace_back(surface, id, e, varies(id));
}

// Unlike Radiance, which ignores them, sources inside instanced octrees light the scene: each placement's
// emitting surfaces are moved into the world and sampled like the scene's own. (Emitting mesh triangles are
// found only by the rays that meet them.)
void RenderScene::addPlacedLights() {
    const auto& placements = geometry_->placements();
    for (int p = 0; p < static_cast<int>(placements.size()); ++p) {
        const Prototype& prototype = geometry_->prototypes()[placements[p].prototype];
        for (int s = prototype.firstSurface; s < prototype.endSurface; ++s) {
            SurfaceId id{s, p};
            int material = materialObject(id);
            if (material < 0 || !emitters_[material]) continue;
            const Surface& local = geometry_->surfaces()[s];
            placedLightSurfaces_.push_back(Surface{local.object, transformed(local.shape, placements[p].transform)});
            addSurfaceLight(placedLightSurfaces_.back(), id);
        }
    }
}

void RenderScene::addSources() {
    const auto& surfaces = geometry_->surfaces();
    surfaceLight_.assign(surfaces.size(), -1);
    for (int s = 0; s < geometry_->ownSurfaces(); ++s) addSurfaceLight(surfaces[s], SurfaceId{s});
    addPlacedLights();
    for (int i = 0; i < static_cast<int>(scene_.ownObjects()); ++i) {  // not in instances, as in Radiance
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
