// Planck's law: the spectral radiance of a black body, as a Spectrum of the sampling in effect in Brume's
// units (a flat spectrum of 1 is Radiance's white, 179 cd/m²), for flames.
#pragma once
#include <vector>

#include "spectrum/spectrum.h"

namespace brume {

// Planck's spectral radiance at `nm` nanometres and `kelvin`, in W·m⁻²·sr⁻¹·nm⁻¹.
double planck(double nm, double kelvin);

// A black body's radiance at `kelvin` (0 at or below 0 K), band averages of 1 nm samples over 360–830 nm; in RGB
// their colour with no grey added where it lies outside the gamut (xyzToRgbWithoutGrey).
Spectrum blackbody(double kelvin);

// blackbody() every kStep kelvin up to kHottest, for flames (Planck per sample costs too much), interpolated
// per band in ln B over 1/T: Wien's ln B = a − c₂/(λT) is linear in 1/T, so that between entries 25 K apart the
// interpolation is off by under 1e-4 of B where a linear one was off by 1 % at 1500 K and 5 % at 1000 K.
class BlackbodyTable {
public:
    static constexpr double kStep = 25, kHottest = 6000;
    BlackbodyTable();
    // B at `kelvin`, clamped to [0, kHottest].
    Spectrum at(double kelvin) const;

private:
    std::vector<Spectrum> radiance_;
    std::vector<std::vector<double>> logRadiance_;  // −∞ where B is 0
};

}  // namespace brume
