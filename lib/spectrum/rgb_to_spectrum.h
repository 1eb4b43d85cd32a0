// Smooth spectra for RGB colours, so that scenes written in RGB render in any number of bands (Jakob and
// Hanika 2019, "A Low-Dimensional Function Space for Efficient Spectral Upsampling"): spectra
// s(λ) = σ(c₀t² + c₁t + c₂), σ(x) = ½ + x / (2√(1 + x²)), t the wavelength scaled to 0…1 over the CIE
// observer's range, whose colour (CIE 1931 observer, Radiance's primaries and equal-energy white) is the
// given RGB. Three coefficients per colour come from a table over the RGB cube, fitted once on first use
// (Gauss–Newton with continuation in brightness, as the paper does) and interpolated trilinearly.
#pragma once
#include <array>

#include "spectrum/spectrum.h"

namespace brume {

// The colour in the sampling in effect: with 3 channels the RGB itself. Greys are flat spectra exactly;
// colours brighter than 1 are lifted at half their maximum and scaled back (σ stays below 1); colours with
// a negative channel become Radiance's box spectra (each channel flat over its partition of the range).
Spectrum spectrumFromRgb(double r, double g, double b);

using SigmoidCoefficients = std::array<double, 3>;
// The table's coefficients for a colour with channels in 0…1, and the spectrum they define at a wavelength.
SigmoidCoefficients sigmoidCoefficients(double r, double g, double b);
double sigmoidSpectrum(const SigmoidCoefficients& c, double nm);

}  // namespace brume
