// The volume irradiance cache: volume records (VolumeZones) in a RecordStore.
#pragma once
#include "cache/record_store.h"
#include "cache/volume_zones.h"

namespace brume {

using VolumeCache = RecordStore<VolumeZones>;

}  // namespace brume
