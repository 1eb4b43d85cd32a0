// Where a lookup found no record: a record could be made there.
#pragma once
#include <cstdint>

#include "geometry/ray.h"
#include "geometry/receiver.h"

namespace brume {

struct RecordRequest {
    Receiver at;          // the point, its normal, the diffuse bounce and the instant of the lookup
    SurfaceId leaving;    // the surface under the point, which the record's rays leave
    float weight = 1;     // the looking ray's weight (fewer samples for records deep in a path, as Radiance)
    uint64_t key = 0;     // seeds the record's samples: the same request gives the same record
};

}  // namespace brume
