// One record of the surface irradiance cache: the indirect irradiance measured at a point of a surface at
// one instant (serving a window of instants, RecordTime), how it changes nearby (Ward & Heckbert 1992's
// gradients, second order in rotation), and the elliptic zone where it stands for its neighbours (Ribardière
// 2010's adaptive records: two tangent axes, each with its own length).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "cache/record_time.h"
#include "spectrum/spectrum.h"

namespace brume {

using glm::dvec3;

struct SurfaceRecord {
    dvec3 point{0};
    dvec3 normal{0, 0, 1};
    dvec3 axis{1, 0, 0};        // k1, a unit tangent; k2 = normal × k1
    float radius[2] = {0, 0};   // the zone's semi-axes along k1 and k2
    int level = 0;              // the diffuse bounce it was computed for (0: seen from a primary ray)
    RecordTime when;            // the instant it holds the light of, and the window it serves
    // Per channel, in this order: irradiance E; its translational gradients along k1, k2 (per metre); its
    // rotational gradients as the normal tilts toward k1, k2 (per radian).
    std::vector<float> values;

    static constexpr int kFields = 5;
    enum Field { kIrradiance, kAlongK1, kAlongK2, kTiltK1, kTiltK2 };

    int channels() const { return int(values.size()) / kFields; }
    size_t heapBytes() const { return values.capacity() * sizeof(float); }
    dvec3 axis2() const { return glm::cross(normal, axis); }
    float value(Field f, int channel) const { return values[size_t(f) * channels() + channel]; }
    Spectrum field(Field f) const {
        Spectrum s(0.f, channels());
        for (int c = 0; c < channels(); ++c) s[c] = value(f, c);
        return s;
    }
    void setField(Field f, const Spectrum& s) {
        if (values.empty()) values.assign(size_t(kFields) * s.size(), 0.f);
        for (int c = 0; c < channels(); ++c) values[size_t(f) * channels() + c] = s[c];
    }
};

}  // namespace brume
