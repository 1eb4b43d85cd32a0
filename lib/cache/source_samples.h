// The sources' light arriving at a volume record's point, as next-event estimation samples it: per sample, the
// direction it came from, the distance to the source's point (infinite for distant sources) and its radiance
// through whatever lies between over its density and the sample count, so that the samples of one source sum
// to ∫ L dω of its light there.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "spectrum/spectrum.h"

namespace brume {

struct SourceSample {
    glm::dvec3 dir;
    double distance;
    Spectrum flux;
};

// One source's samples.
using SourceSamples = std::vector<SourceSample>;

}  // namespace brume
