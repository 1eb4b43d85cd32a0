// Surface records as a kind of cache record (RecordStore's parameter): where each stands for its neighbours
// — an elliptic zone on its plane, normals within Radiance's 10° + -aa — with what weight and value, how its
// zone is boxed for the index, and how two records that disagree shrink their zones.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "cache/record_shape.h"
#include "cache/surface_record.h"
#include "cache/zone_index.h"
#include "geometry/receiver.h"

namespace brume {

class SurfaceZones {
public:
    using Record = SurfaceRecord;

    explicit SurfaceZones(const RecordShape& shape);
    const RecordShape& shape() const { return shape_; }

    // The record's weight at the receiver (its point and normal), 0 outside its zone: (|RP'|/|RP| − 1)(1 −
    // α/α_max), P' where the ray from the record through P leaves the ellipse (Ribardière 2010). With `value`,
    // also the record's extrapolation to the receiver by its gradients.
    double weigh(const SurfaceRecord& r, const Receiver& at, Spectrum* value) const;
    // A box holding the zone, measured from `origin`; and the radius about the record's point that holds it.
    ZoneBox box(const SurfaceRecord& r, const dvec3& origin) const;
    double reach(const SurfaceRecord& r) const { return std::max(r.radius[0], r.radius[1]); }
    // Misses are counted apart for receivers facing different ways: the dominant axis of the normal, and
    // its sign.
    int facing(const Receiver& at) const {
        const dvec3& n = *at.normal;
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
        return axis * 2 + (n[axis] < 0);
    }
    // The size of a typical record (its short radius), and that assumed before any record is made.
    double size(const SurfaceRecord& r) const { return r.radius[0]; }
    double sizeBeforeRecords() const;
    // Splotch control between a new record and an older one of its bounce: each must agree with the
    // other's value, within twice the accuracy, where its zone holds the other; else that zone shrinks to
    // leave the other out (by at most half at a time: either may be the noisy one).
    void reconcile(SurfaceRecord& fresh, SurfaceRecord& older) const;

    // How bright the record's irradiance is (RecordWindows weighs how its light changes in time by it).
    static double brightnessOf(const SurfaceRecord& r) { return brume::brightness(r.field(SurfaceRecord::kIrradiance)); }
    // Records of one point at the instants of a window, made to share the first's zone: its axes (the others'
    // gradients turned to them) and the largest ellipse about them inside every record's zone.
    static void shareZone(std::vector<SurfaceRecord>& records);

private:
    void shrinkToExclude(SurfaceRecord& holder, const SurfaceRecord& other) const;

    RecordShape shape_;
    double cosMaxAngle_;
};

}  // namespace brume
