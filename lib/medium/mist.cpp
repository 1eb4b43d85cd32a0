#include "medium/mist.h"

#include <cmath>

#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

Mist readMist(const SceneObject& o) {
    auto bad = [&](const std::string& what) { return Error(o.where, "bad mist '" + o.name + "': " + what); };
    const std::vector<double>& r = o.reals;
    if (!o.integers.empty() || r.size() > 7) throw bad("expected 0 to 7 reals");
    Mist mist;
    mist.sources = o.strings;
    auto rgb = [&](size_t i) { return spectrumFromRgb(float(r[i]), float(r[i + 1]), float(r[i + 2])); };
    if (r.size() >= 3) {
        if (!(r[0] >= 0 && r[1] >= 0 && r[2] >= 0)) throw bad("extinction must be positive or 0");
        mist.extinction = rgb(0);
    }
    if (r.size() >= 6) {
        for (size_t i = 3; i < 6; ++i)
            if (!(r[i] >= 0 && r[i] <= 1)) throw bad("albedo must be between 0 and 1");
        mist.albedo = rgb(3);
    }
    if (r.size() == 7) {
        if (!(std::abs(r[6]) < 1)) throw bad("eccentricity g must be between -1 and 1");
        mist.g = r[6];
    }
    return mist;
}

}  // namespace brume
