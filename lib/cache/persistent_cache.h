// An irradiance cache kept in an -af file: its records (surface records, and volume records where a medium
// scatters) are loaded when the program starts, and those it makes are appended after each batch of work,
// where other processes sharing the file find them.
#pragma once
#include <memory>
#include <string>

#include "cache/cache_file.h"
#include "cache/surface_cache.h"
#include "cache/volume_cache.h"

namespace brume {

class PersistentCache {
public:
    // Opens (or creates) `path` for the scene and options `identity` names, and loads its records into
    // `cache` and `volumes` (null where no medium scatters: the file then holds none). Throws Error when
    // the file belongs to another scene or other options, or is damaged.
    PersistentCache(const std::string& path, const CacheIdentity& identity, SurfaceCache& cache, VolumeCache* volumes);
    // Appends the records made since the last call, and loads those other processes appended meanwhile.
    // Not while the caches are in use.
    void sync();

private:
    void load();
    CacheFile file_;
    SurfaceCache& cache_;
    VolumeCache* volumes_;
};

}  // namespace brume
