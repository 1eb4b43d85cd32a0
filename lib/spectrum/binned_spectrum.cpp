#include "spectrum/binned_spectrum.h"

#include <algorithm>

#include "spectrum/cie_tables.h"
#include "spectrum/colorimetry.h"
#include "spectrum/spectral_sampling.h"

namespace brume {

namespace {

// The bins' colour: each bin's value times each curve's share of its area in the bin.
Spectrum colourOfBins(std::span<const double> values, double from, double step, Gamut gamut) {
    const TabulatedSpectrum* curves[3] = {&cieX(), &cieY(), &cieZ()};
    Color3 xyz{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
        const TabulatedSpectrum& f = *curves[c];
        double area = f.integral(f.first, f.last());
        for (size_t j = 0; j < values.size(); ++j) {
            double a = from + double(j) * step, b = a + step;
            xyz[size_t(c)] += values[j] * f.integral(std::min(a, b), std::max(a, b)) / area;
        }
    }
    Color3 rgb = gamut == Gamut::Clipped ? xyzToClippedRgb(xyz) : xyzToRgbWithoutGrey(xyz);
    return Spectrum(float(rgb[0]), float(rgb[1]), float(rgb[2]));
}

}  // namespace

Spectrum spectrumFromBins(std::span<const double> values, double from, double to, Gamut gamut) {
    double step = (to - from) / double(values.size());
    const SpectralSampling& s = spectralSampling();
    if (values.empty() || !(step != 0)) return Spectrum(0.f);
    if (s.isRgb()) return colourOfBins(values, from, step, gamut);
    Spectrum out(0.f, s.channels);
    for (int i = 0; i < s.channels; ++i) {
        auto band = s.band(i);  // longer, shorter
        double sum = 0;
        for (size_t j = 0; j < values.size(); ++j) {
            double a = from + double(j) * step, b = a + step;
            double overlap = std::min(band[0], std::max(a, b)) - std::max(band[1], std::min(a, b));
            if (overlap > 0) sum += values[j] * overlap;
        }
        out[i] = float(sum / (band[0] - band[1]));
    }
    return out;
}

}  // namespace brume
