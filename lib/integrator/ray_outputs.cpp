#include "integrator/ray_outputs.h"

#include <cmath>

namespace brume {

RayOutputs::TreeRay::TreeRay(RayOutputs& outputs, const dvec3& org, const dvec3& dir)
    : outputs_(outputs), org_(org), dir_(dir) {
    own_.point = org;
    scope_.emplace(outputs, outputs.record_ ? outputs.record_ : &own_);
    ++outputs.depth_;
}

void RayOutputs::TreeRay::end(const Spectrum& value) {
    --outputs_.depth_;
    RayRecord& record = *outputs_.record_;
    record.value = value;
    outputs_.tree_->rays.push_back({outputs_.depth_, org_, dir_, record});
}

void RayOutputs::endSensor(const dvec3& point, const dvec3& dir, RayRecord& record, const Spectrum& value) {
    if (!tree_) return;
    record.value = value;
    tree_->rays.push_back({0, point, dir, record});
}

void RayOutputs::distantSource(int object, int modifier, const dvec3& dir) {
    record_->surfaceObject = object;
    record_->modifierObject = modifier;
    record_->normal = record_->surfaceNormal = -dir;
}

void RayOutputs::passedThrough(const RayRecord& beyond, double distance) {
    *record_ = beyond;
    record_->firstLength += distance;
    record_->effectiveLength += distance;
}

void RayOutputs::specularPart(const Spectrum& part, bool reflection, const RayRecord& child, double& strongest) {
    double b = brightness(part);
    if (reflection) {
        record_->mirrored += part;
        record_->mirroredLength = record_->firstLength + child.effectiveLength;
    }
    if (b > strongest) {
        strongest = b;
        record_->effectiveLength = record_->firstLength + child.effectiveLength;
    }
}

void RayOutputs::shadowRay(const dvec3& from, const LightSample& s, int object, int modifier, const Spectrum& value) {
    RayRecord shadow;
    shadow.value = value;
    shadow.firstLength = shadow.effectiveLength = s.distance;
    shadow.point = from + (std::isfinite(s.distance) ? s.distance : 0.0) * s.dir;
    shadow.surfaceObject = object;
    shadow.modifierObject = modifier;
    tree_->rays.push_back({depth_, from, s.dir, shadow});
}

}  // namespace brume
