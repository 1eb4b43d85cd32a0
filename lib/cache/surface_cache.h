// The surface irradiance cache: surface records (SurfaceZones) in a RecordStore.
#pragma once
#include "cache/record_store.h"
#include "cache/surface_zones.h"

namespace brume {

using SurfaceCache = RecordStore<SurfaceZones>;

}  // namespace brume
