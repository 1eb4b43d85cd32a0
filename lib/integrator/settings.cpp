#include "integrator/settings.h"

#include <chrono>

#include "sampling/random.h"
#include "spectrum/rgb_to_spectrum.h"

namespace brume {

uint64_t runSeed(const RenderSettings& settings) {
    return settings.randomSampling
               ? mixBits(static_cast<uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()))
               : settings.seed;
}

RenderSettings inBands(RenderSettings s) {
    auto lift = [](Spectrum& c) {
        if (c.size() == 3) c = spectrumFromRgb(c[0], c[1], c[2]);
    };
    lift(s.ambientValue);
    lift(s.medium.extinction);
    lift(s.medium.albedo);
    return s;
}

}  // namespace brume
