// Volume records as a kind of cache record (RecordStore's parameter): a sphere about each record's point where
// it stands for its neighbours, with what weight; the light it says a medium scatters toward a ray there; how
// its zone is boxed for the index; and how two records that disagree shrink their zones.
#pragma once
#include <array>
#include <vector>

#include "cache/record_shape.h"
#include "cache/volume_record.h"
#include "cache/zone_index.h"
#include "geometry/receiver.h"
#include "medium/phase_mixture.h"

namespace brume {

class VolumeZones {
public:
    using Record = VolumeRecord;

    explicit VolumeZones(const RecordShape& shape) : shape_(shape) {}
    const RecordShape& shape() const { return shape_; }

    // The record's weight at the receiver's point, 1/q − 1 with q its distance over the zone's radius (0
    // outside). With `value`, the mean radiance arriving there, extrapolated by the record's gradient.
    double weigh(const VolumeRecord& r, const Receiver& at, Spectrum* value) const;
    // What the record says `phase` at p scatters back along a ray of direction dir, given Y_k(dir) as `basis`
    // (shBasis: one per lookup, whatever the records): Σ over the lobes of coefficient × (Σ_k g^l c_k(p) Y_k(dir),
    // at least 0 per channel, + Σ over the peaks of flux(p) × p_g(ω(p)·dir)), the coefficients extrapolated to p
    // by their gradients (by at most as much as would zero or double the mean), the peaks moved there as point
    // sources; the sources' peaks only with `sources`.
    static Spectrum scattered(const VolumeRecord& r, const dvec3& p, const dvec3& dir,
                              const std::array<double, kShCount>& basis, const PhaseMixture& phase, bool sources);

    ZoneBox box(const VolumeRecord& r, const dvec3& origin) const;
    double reach(const VolumeRecord& r) const { return r.radius; }
    // Every receiver in a medium faces every way.
    int facing(const Receiver&) const { return 0; }
    double size(const VolumeRecord& r) const { return r.radius; }
    double sizeBeforeRecords() const;
    // Splotch control, as surface records': each must agree with the other's mean radiance within twice the
    // accuracy where its zone holds the other, else that zone shrinks to leave it out (by at most half).
    void reconcile(VolumeRecord& fresh, VolumeRecord& older) const;

    // How bright the light arriving at the record's point is (RecordWindows weighs how it changes in time by it).
    static double brightnessOf(const VolumeRecord& r) { return brume::brightness(r.meanRadiance()); }
    // Records of one point at the instants of a window, made to share one zone: the smallest of theirs.
    static void shareZone(std::vector<VolumeRecord>& records);

private:
    void shrinkToExclude(VolumeRecord& holder, const VolumeRecord& other) const;

    RecordShape shape_;
};

}  // namespace brume
