// Where Embree's single precision can be trusted. A model at its site coordinates (UTM: x ~ 5e5, y ~ 5e6 m)
// would round to half a metre in floats; Embree is given coordinates relative to a local origin found from
// the geometry itself (the median of its items' centres), so a model has the same float coordinates
// wherever it stands. Items far larger than the typical one (a ground polygon 2000 km wide) or far from the
// rest (a ball 1e12 m away) are told apart, so that they neither round the others nor set the scene's scale.
#pragma once
#include <vector>

#include "geometry/bounds.h"

namespace brume {

// A bound on Embree's float rounding, relative to the size of the coordinates it rounds: 16 float ulps
// (2^-24 each), room for the few operations of its robust triangle and box tests.
constexpr double kFloatError = 16.0 / (1 << 24);

class LocalFrame {
public:
    LocalFrame() = default;
    // From the boxes of a group's items (surfaces, placed copies); empty boxes are ignored. A prototype's
    // items are also huge beside `outerTypical`, the typical item of the world it is placed in (in its units).
    explicit LocalFrame(const std::vector<Bounds3>& items, double outerTypical = 1e300);

    // Embree's coordinates are offsets from this point.
    const dvec3& origin() const { return origin_; }
    // The lower median of the items' diagonals: the group's typical item.
    double typicalSize() const { return typical_; }
    // Far larger than the typical item (10³ times): exact double-precision geometry rather than float
    // triangles, and left out of the scene's scale.
    bool huge(const Bounds3& b) const;
    // Wholly within 10⁴ typical sizes of the origin, where float rounding stays below ~10⁻³ of a typical item.
    bool near(const Bounds3& b) const;
    // Coming within 10⁴ typical sizes of the origin (a huge box around it does).
    bool reaches(const Bounds3& b) const;

private:
    dvec3 origin_{0};
    double typical_ = 1, hugeSize_ = 1e3;
};

// The largest |coordinate| of the box's corners relative to `origin`.
double reachFrom(const Bounds3& b, const dvec3& origin);

}  // namespace brume
