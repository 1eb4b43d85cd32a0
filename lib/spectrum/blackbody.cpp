#include "spectrum/blackbody.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
    return spectrumFromBins(bins, kFirst - 0.5, kLast + 0.5, Gamut::WithoutGrey);
}

BlackbodyTable::BlackbodyTable() {
    for (double kelvin = 0; kelvin <= kHottest; kelvin += kStep) {
        Spectrum b = blackbody(kelvin);
        std::vector<double> logs(size_t(b.size()));
        for (int c = 0; c < b.size(); ++c)
            logs[size_t(c)] = b[c] > 0 ? std::log(double(b[c])) : -std::numeric_limits<double>::infinity();
        radiance_.push_back(b);
        logRadiance_.push_back(std::move(logs));
    }
}

Spectrum BlackbodyTable::at(double kelvin) const {
    kelvin = std::clamp(kelvin, 0.0, kHottest);
    const size_t i = std::min(size_t(kelvin / kStep), radiance_.size() - 2);
    const double t0 = double(i) * kStep, t1 = t0 + kStep, w = (kelvin - t0) / kStep;
    const double inverse = kelvin > 0 && t0 > 0 ? (1 / kelvin - 1 / t0) / (1 / t1 - 1 / t0) : w;
    const Spectrum &b0 = radiance_[i], &b1 = radiance_[i + 1];
    Spectrum out(0.f, b0.size());
    for (int c = 0; c < out.size(); ++c) {
        const double l0 = logRadiance_[i][size_t(c)], l1 = logRadiance_[i + 1][size_t(c)];
        out[c] = std::isfinite(l0) && std::isfinite(l1) ? float(std::exp(l0 + inverse * (l1 - l0)))
                                                        : float((1 - w) * b0[c] + w * b1[c]);
    }
    return out;
}

}  // namespace brume
