#include "spectrum/spectral_sampling.h"

#include <cstdio>

#include "spectrum/colorimetry.h"
#include "spectrum/spectrum.h"
#include "util/error.h"
#include "util/options.h"

namespace brume {

namespace {

SpectralSampling gSampling;

}  // namespace

std::array<double, 4> SpectralSampling::splits() const {
    // The peaks of Radiance's red, green and blue primaries must lie in the range for the standard splits.
    if (shortest >= 469 || longest <= 607)
        return {longest, longest + (shortest - longest) / 3, longest + 2 * (shortest - longest) / 3, shortest};
    return {longest, 588, 480, shortest};
}

std::array<double, 2> SpectralSampling::band(int i) const {
    if (isRgb()) {
        auto s = splits();
        return {s[size_t(i)], s[size_t(i) + 1]};
    }
    double w = (longest - shortest) / channels;
    return {longest - i * w, longest - (i + 1) * w};
}

const SpectralSampling& spectralSampling() { return gSampling; }

bool validSpectralRange(double shortest, double longest) {
    return longest - shortest >= 50 && shortest >= 200 && longest <= 2000;
}

void setSpectralSampling(SpectralSampling s) {
    std::string option = "-cs " + std::to_string(s.channels);
    if (s.channels < 3) throw Error(option + ": at least 3 spectral samples");
    if (s.channels > Spectrum::kMaxChannels)
        throw Error(option + ": at most " + std::to_string(Spectrum::kMaxChannels) + " spectral samples");
    if (s.longest < s.shortest) std::swap(s.longest, s.shortest);
    if (!validSpectralRange(s.shortest, s.longest))
        throw Error("-cw " + formatShort(s.shortest) + " " + formatShort(s.longest) +
                    ": the spectral range must span 50 nm or more within 200 to 2000 nm");
    gSampling = s;
    remakeObserverWeights();
    if (s.isRgb()) {
        Spectrum::setDefaultChannels(3);
        return;
    }
    const std::vector<double>& y = observerWeights().y;
    double sum = 0;
    for (double w : y) sum += w;
    float weights[Spectrum::kMaxChannels];
    for (int i = 0; i < s.channels; ++i) weights[i] = float(sum > 0 ? y[size_t(i)] / sum : 1. / s.channels);
    Spectrum::setDefaultChannels(s.channels, weights);
}

std::string samplingOptions(const SpectralSampling& s) {
    return "-cs " + std::to_string(s.channels) + " -cw " + formatShort(s.shortest) + " " + formatShort(s.longest);
}

}  // namespace brume
