// Planck's law: the spectral radiance of a black body, as a Spectrum of the sampling in effect in Brume's
// units (a flat spectrum of 1 is Radiance's white, 179 cd/m²), for flames.
#pragma once
#include "spectrum/spectrum.h"

namespace brume {

// Planck's spectral radiance at `nm` nanometres and `kelvin`, in W·m⁻²·sr⁻¹·nm⁻¹.
double planck(double nm, double kelvin);

// A black body's radiance at `kelvin` (0 at or below 0 K), band averages of 1 nm samples over 360–830 nm.
Spectrum blackbody(double kelvin);

}  // namespace brume
