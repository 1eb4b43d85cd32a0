// One record of the volume irradiance cache: the indirect light arriving from every direction at a point in
// a medium at one instant, as the coefficients of real spherical harmonics up to order 2 per channel (enough
// for the shape a Henyey–Greenstein phase function sees of it: the lobe keeps g^l of order l), how they
// change as the point moves (per metre along x, y and z), and the sphere about the point where it stands
// for its neighbours.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "sampling/spherical_harmonics.h"
#include "spectrum/spectrum.h"

namespace brume {

struct VolumeRecord {
    glm::dvec3 point{0};
    float radius = 0;  // the zone's
    int level = 0;     // the bounce it was computed for (0: seen from a primary ray)
    double time = 0;   // the scene's instant (s)
    // values[((field × 9) + k) × channels + c]: field 0 the coefficient of Y_k in channel c, fields 1–3 its
    // gradient along x, y, z.
    std::vector<float> values;

    static constexpr int kFields = 4;

    int channels() const { return int(values.size()) / (kFields * kShCount); }
    float value(int field, int k, int channel) const { return values[(size_t(field) * kShCount + k) * channels() + channel]; }
    // The mean radiance arriving over the sphere (the fluence over 4π) at the record's point, per channel.
    Spectrum meanRadiance() const {
        Spectrum s(0.f, channels());
        for (int c = 0; c < channels(); ++c) s[c] = value(0, 0, c) * float(kShY0);
        return s;
    }
};

}  // namespace brume
