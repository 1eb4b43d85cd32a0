// An irradiance cache kept in an -af file: its records are loaded when the program starts, and those it
// makes are appended after each batch of work, where other processes sharing the file find them.
#pragma once
#include <memory>
#include <string>

#include "cache/cache_file.h"
#include "cache/surface_cache.h"

namespace brume {

class PersistentCache {
public:
    // Opens (or creates) `path` for the scene and options `identity` names, and loads its records into
    // `cache`. Throws Error when the file belongs to another scene or other options, or is damaged.
    PersistentCache(const std::string& path, const CacheIdentity& identity, SurfaceCache& cache);
    // Appends the records made since the last call, and loads those other processes appended meanwhile.
    // Not while the cache is in use.
    void sync();

private:
    void load();
    CacheFile file_;
    SurfaceCache& cache_;
};

}  // namespace brume
