// One record of the volume irradiance cache: the light arriving from every direction at a point in a medium
// at one instant (serving a window of instants, RecordTime), as the coefficients of real spherical harmonics
// up to order 2 per channel (enough for the shape a Henyey–Greenstein phase function sees of smooth light:
// the lobe keeps g^l of order l), how they change as the point moves (per metre along x, y and z), and the sphere about the point where it stands
// for its neighbours. Light far brighter than the rest from a few directions (the glow a lamp makes in the
// medium around it) is kept apart as peaks, single samples the phase function weighs exactly: order 2 cannot
// hold a narrow peak (under HG .6 it would scatter 0.37 in place of 0.80 sr⁻¹ of it forward, 0.08 in place of
// 0.012 backward). The sources' light (what next-event estimation gives) is held too, as the last peaks, one to
// 36 per source by direction, so that a ray through the medium takes it from the records, as averaged over
// many shadow rays, rather than from a few of its own; lookups whose ray took the sources' light elsewhere
// leave these out.
#pragma once
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

#include "cache/record_time.h"
#include "sampling/spherical_harmonics.h"
#include "spectrum/spectrum.h"

namespace brume {

struct VolumeRecord {
    glm::dvec3 point{0};
    float radius = 0;  // the zone's
    int level = 0;     // the bounce it was computed for (0: seen from a primary ray)
    RecordTime when;   // the instant it holds the light of, and the window it serves
    // values[((field × 9) + k) × channels + c]: field 0 the coefficient of Y_k in channel c, fields 1–3 its
    // gradient along x, y, z.
    std::vector<float> values;
    // Per peak: the direction its light came from and the inverse of the distance its ray went (0: no
    // surface), and peakFlux[peak × channels + c], its radiance above the harmonics' share times its solid angle.
    std::vector<glm::vec4> peakRays;
    std::vector<float> peakFlux;
    int sourcePeaks = 0;  // the last peaks are the sources'

    static constexpr int kFields = 4;

    int channels() const { return int(values.size()) / (kFields * kShCount); }
    int peaks() const { return int(peakRays.size()); }
    // The peaks a lookup takes: all, or those of the light that did not come straight from the sources.
    int peaksWith(bool sources) const { return sources ? peaks() : peaks() - sourcePeaks; }
    size_t heapBytes() const {
        return (values.capacity() + peakFlux.capacity()) * sizeof(float) + peakRays.capacity() * sizeof(glm::vec4);
    }
    float value(int field, int k, int channel) const { return values[(size_t(field) * kShCount + k) * channels() + channel]; }
    float flux(int peak, int channel) const { return peakFlux[size_t(peak) * channels() + channel]; }
    // The mean radiance arriving over the sphere (the fluence over 4π) at the record's point, per channel.
    Spectrum meanRadiance() const {
        Spectrum s(0.f, channels());
        for (int c = 0; c < channels(); ++c) {
            double sum = value(0, 0, c) * kShY0;
            for (int i = 0; i < peaks(); ++i) sum += flux(i, c) / (4 * std::numbers::pi);
            s[c] = float(sum);
        }
        return s;
    }
};

}  // namespace brume
