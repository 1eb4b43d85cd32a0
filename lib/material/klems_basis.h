// Klems angle bases (LBNL/WINDOW): the hemisphere cut into rings of polar angle, each ring into equal
// azimuthal patches, the first patch of each ring centred on azimuth 0 (the local x axis). Directions
// here are in the BSDF's local frame on the side the basis describes (z ≥ 0); see KlemsSide for the
// other three ways a matrix uses a basis.
#pragma once
#include <string>
#include <vector>

#include "geometry/ray.h"

namespace brume {

class KlemsBasis {
public:
    struct Ring {
        double lowerTheta, upperTheta;  // degrees
        int phis;
    };
    KlemsBasis(std::string name, std::vector<Ring> rings);
    // LBNL/Klems Full (145 patches), Half (77) and Quarter (41), as Radiance defines them; nullptr for
    // another name.
    static const KlemsBasis* standard(const std::string& name);

    const std::string& name() const { return name_; }
    int size() const { return size_; }
    // The patch holding unit direction d (z ≥ 0), or -1 (below the horizon).
    int index(const dvec3& d) const;
    // A direction in patch p, uniform in projected solid angle for (u, v) uniform in [0, 1)².
    dvec3 direction(int p, double u, double v) const;
    // The patch's projected solid angle ∫cos θ dω.
    double projectedSolidAngle(int p) const { return ohm_[size_t(p)]; }

private:
    int ring(int p, int& within) const;
    std::string name_;
    std::vector<Ring> rings_;
    std::vector<double> cosUpper_;  // per ring: cos of its upper polar angle, for finding rings without acos
    std::vector<double> ohm_;
    int size_ = 0;
};

// How a BSDF matrix reads a basis for one of its two directions (both point away from the surface):
// directions on the back side (z < 0) are mirrored through the surface, and incident directions are
// turned half way round in azimuth, so that the patch of straight-through transmission and of mirror
// reflection has the same index as the incident one (Radiance's bsdf_m.c conventions).
struct KlemsSide {
    bool front;     // z > 0
    bool incident;  // azimuth turned by 180°

    // The patch of `d` (local frame), or -1 when d is on the other side.
    int index(const KlemsBasis& b, const dvec3& d) const;
    dvec3 direction(const KlemsBasis& b, int p, double u, double v) const;
};

}  // namespace brume
