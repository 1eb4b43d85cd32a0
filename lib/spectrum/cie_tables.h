// The CIE's observer, efficiency, action-spectrum and illuminant tables, read from the CIE's own CSV files
// compiled into the library (lib/spectrum/cie/, sources in its README). Each is parsed once, on first use,
// safely from any thread.
#pragma once
#include <vector>

namespace brume {

// A function of wavelength given at equal steps, linear between them, zero outside.
struct TabulatedSpectrum {
    double first = 0, step = 1;  // nm
    std::vector<double> values;
    double last() const;         // first + step·(values.size()−1)
    double at(double nm) const;  // linear interpolation, 0 outside [first, last]
    // Exact integral over [lo, hi] (nm) of the piecewise-linear function (0 outside its range).
    double integral(double lo, double hi) const;
};

const TabulatedSpectrum& cieX();  // CIE 1931 2° x̄, ȳ, z̄
const TabulatedSpectrum& cieY();
const TabulatedSpectrum& cieZ();
const TabulatedSpectrum& scotopicEfficiency();   // V'(λ)
const TabulatedSpectrum& melanopicEfficiency();  // s_mel(λ), CIE S 026
const TabulatedSpectrum& illuminantA();          // relative SPD, 100 at 560 nm
const TabulatedSpectrum& illuminantD65();        // relative SPD, 100 at 560 nm

}  // namespace brume
