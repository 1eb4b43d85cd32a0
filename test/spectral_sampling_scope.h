// Tests that render in bands: the sampling in effect for the test's scope, RGB again after it.
#pragma once
#include "spectrum/spectral_sampling.h"

namespace brume {

struct SpectralSamplingScope {
    explicit SpectralSamplingScope(int channels, double shortest = 380, double longest = 780) {
        setSpectralSampling({channels, longest, shortest});
    }
    ~SpectralSamplingScope() { setSpectralSampling({}); }
};

}  // namespace brume
