#include "integrator/settings.h"

#include "spectrum/rgb_to_spectrum.h"

namespace brume {

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
