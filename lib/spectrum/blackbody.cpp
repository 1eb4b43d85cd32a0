#include "spectrum/blackbody.h"

#include <cmath>
#include <vector>

#include "spectrum/binned_spectrum.h"
#include "spectrum/colorimetry.h"

namespace brume {

double planck(double nm, double kelvin) {
    constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    const double lambda = nm * 1e-9;
    const double perMetre = 2 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * kelvin));
    return perMetre * 1e-9;
}

Spectrum blackbody(double kelvin) {
    if (!(kelvin > 0)) return Spectrum(0.f);
    constexpr double kFirst = 360, kLast = 830;
    std::vector<double> bins;  // 1 nm bins centred on whole nanometres
    const double perValue = spectralRadiancePerValue();
    for (double nm = kFirst; nm <= kLast; nm += 1) bins.push_back(planck(nm, kelvin) / perValue);
    return spectrumFromBins(bins, kFirst - 0.5, kLast + 0.5);
}

}  // namespace brume
