// Spectra given as bins of equal width (the spectrum primitive's values, a data file's samples, a function
// sampled across a range), brought into the sampling in effect as Radiance's convertscolorcol does.
#pragma once
#include <span>

#include "spectrum/spectrum.h"

namespace brume {

// `values` are bins of equal width from wavelength `from` to `to` (nm, either order: values[0] is the bin at
// `from`). Each band gets the bins' average over it, zero where they do not reach; with 3 channels, the
// bins' colour (CIE 1931 observer, Radiance's primaries, negatives clipped as Radiance's clipgamut, or with
// Gamut::WithoutGrey by xyzToRgbWithoutGrey).
enum class Gamut { Clipped, WithoutGrey };
Spectrum spectrumFromBins(std::span<const double> values, double from, double to, Gamut gamut = Gamut::Clipped);

}  // namespace brume
