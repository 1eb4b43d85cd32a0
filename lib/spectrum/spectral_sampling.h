// How values of light are sampled in wavelength (Radiance 6's -cs N and -cw lo hi): N bands of equal width
// between the extrema, the longest wavelength first as Radiance orders them; 3 bands are RGB, whose "bands"
// are Radiance's red/green/blue partitions of the range (WAVELENGTH_SPLITS).
#pragma once
#include <array>
#include <string>

namespace brume {

struct SpectralSampling {
    int channels = 3;
    double longest = 780, shortest = 380;  // nm

    bool isRgb() const { return channels == 3; }
    // Radiance's WAVELENGTH_SPLITS: longest, red/green, green/blue, shortest. Ranges that miss a primary's
    // peak are split in thirds, as Radiance does.
    std::array<double, 4> splits() const;
    // Band i's edges (longer, shorter); for RGB the partitions between the splits.
    std::array<double, 2> band(int i) const;
    double bandCentre(int i) const {
        auto b = band(i);
        return 0.5 * (b[0] + b[1]);
    }
    bool operator==(const SpectralSampling&) const = default;
};

// Whether a range of wavelengths (nm) is one Brume samples: 50 nm or more within 200 to 2000 nm.
bool validSpectralRange(double shortest, double longest);

// The sampling in effect. Set it once, from the options, before anything makes a Spectrum that lasts.
const SpectralSampling& spectralSampling();
// Checks `s` as Radiance does (Error "-cs N: …" for fewer than 3 or more than Spectrum::kMaxChannels
// samples, a range under 50 nm or outside 200…2000 nm), orders its extrema and makes it the sampling in
// effect, with Spectrum's default channel count and brightness weights.
void setSpectralSampling(SpectralSampling s);

// "-cs N -cw lo hi": the options that reproduce a sampling (cache files record it).
std::string samplingOptions(const SpectralSampling& s);

}  // namespace brume
