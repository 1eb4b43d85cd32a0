// A medium of the same density everywhere: Radiance's global medium (-me, -ma, -mg) and the inside of its
// mists. Extinction and albedo per band; Henyey–Greenstein g.
#pragma once
#include <cmath>

#include "spectrum/spectrum.h"

namespace brume {

struct HomogeneousMedium {
    Spectrum extinction{0.f};  // σ_t per world unit
    Spectrum albedo{0.f};      // σ_s / σ_t
    double g = 0;

    bool clear() const { return !(extinction.maxValue() > 0); }
    bool scatters() const { return !clear() && !(extinction * albedo).isBlack(); }
    // e^{−σ_t·length} per band; over an infinite length 0 wherever σ_t > 0.
    Spectrum transmittance(double length) const {
        Spectrum t(1.f, extinction.size());
        for (int i = 0; i < t.size(); ++i)
            if (extinction[i] > 0) t[i] = float(std::exp(-double(extinction[i]) * length));
        return t;
    }
};

}  // namespace brume
