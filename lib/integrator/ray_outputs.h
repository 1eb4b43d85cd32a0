// rtrace's outputs of a ray (its -o letters: lengths, the point, normals, the object and modifier met, the
// part mirrored), and with -ot/-oT every ray of its tree, collected beside the transport: the transport says
// what a ray meets and how its specular children contributed; a ray's record is filled only where someone
// asks for it (the primary ray, the children its lengths come through, a record's hemisphere rays).
#pragma once
#include <optional>

#include "io/ray_record.h"
#include "light/light.h"
#include "world/scene_geometry.h"

namespace brume {

class RayOutputs {
public:
    // `tree`, when given, receives every ray traced, children before their parent.
    explicit RayOutputs(RayTree* tree = nullptr) : tree_(tree) {}

    // The record of the ray being traced, or null where no one asks for it.
    RayRecord* record() const { return record_; }
    RayTree* tree() const { return tree_; }

    // While it lives, the rays traced report to `record` (null: to none); then the ray before resumes.
    class Scope {
    public:
        Scope(RayOutputs& outputs, RayRecord* record) : outputs_(outputs), before_(outputs.record_) {
            outputs.record_ = record;
        }
        ~Scope() { outputs_.record_ = before_; }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        RayOutputs& outputs_;
        RayRecord* before_;
    };

    // A ray of the tree (only with one): it takes the record asked for, or one of its own, one level deeper;
    // end() adds it to the tree after its children.
    class TreeRay {
    public:
        TreeRay(RayOutputs& outputs, const dvec3& org, const dvec3& dir);
        void end(const Spectrum& value);
        TreeRay(const TreeRay&) = delete;
        TreeRay& operator=(const TreeRay&) = delete;

    private:
        RayOutputs& outputs_;
        dvec3 org_, dir_;
        RayRecord own_;
        std::optional<Scope> scope_;
    };

    // A sensor (rtrace -I, -i) stands for a primary ray: the rays traced for it are its children in the tree,
    // and it is added to the tree, at depth 0, as a ray from `point` in direction `dir`.
    void beginSensor() { depth_ = tree_ ? 1 : 0; }
    void endSensor(const dvec3& point, const dvec3& dir, RayRecord& record, const Spectrum& value);

    // What the transport says of the ray being traced, where its record is asked for (record() is set):
    // The ray met a surface, shaded by `material` (or an emitter).
    void hit(const SurfaceHit& hit, const dvec3& shadingNormal, int surfaceObject, int material) {
        record_->firstLength = record_->effectiveLength = hit.t;
        record_->point = hit.point;
        record_->normal = shadingNormal;
        record_->surfaceNormal = hit.normal;
        record_->uv = hit.uv;
        record_->surfaceObject = surfaceObject;
        record_->modifierObject = material;
    }
    // The ray met a source at infinity (named, facing the ray, at no distance).
    void distantSource(int object, int modifier, const dvec3& dir);
    // The ray went on through a surface `distance` along it that does not shade it (antimatter, a mist's, a
    // void or cut-away one, an emitter's back, an illum without material): its record is the onward ray's
    // `beyond`, lengths counted from this ray's origin.
    void passedThrough(const RayRecord& beyond, double distance);
    // A specular child of the ray brought `part` of its value (by reflection or transmission); its record
    // `child`. `strongest` keeps the brightest part so far, whose lengths the ray's effective length takes.
    void specularPart(const Spectrum& part, bool reflection, const RayRecord& child, double& strongest);
    // The ray's value at a shaded hit, once every lobe is in: where no specular part dominates (less than
    // half of it), the effective length is the first surface's.
    void shaded(const Spectrum& value, double strongest) {
        if (brightness(value) > 0 && strongest < 0.5 * brightness(value)) record_->effectiveLength = record_->firstLength;
    }
    // With -oT: a shadow ray toward a source, and what it brought.
    bool wantsShadowRays() const { return tree_ && tree_->withShadowRays; }
    void shadowRay(const dvec3& from, const LightSample& s, int object, int modifier, const Spectrum& value);

private:
    RayTree* tree_;
    RayRecord* record_ = nullptr;
    int depth_ = 0;  // of the ray being traced in its tree
};

}  // namespace brume
