// An irradiance cache kept in an -af file: its records are loaded when the program starts, and those it
// makes are appended after each batch of work, where other processes sharing the file find them.
#pragma once
#include <memory>
#include <string>

#include "cache/cache_file.h"
#include "cache/irradiance_cache.h"
#include "integrator/settings.h"
#include "scene/scene.h"

namespace brume {

// Every option that changes cached values, as text (with Brume's version): a cache file made with other
// options is refused.
std::string cacheOptions(const RenderSettings& settings);

class PersistentCache;

// The -af file of these settings for `cache`, opened (null when -af is not given, or, with a warning, when
// there is no cache to keep: -ab or -aa 0).
std::unique_ptr<PersistentCache> openCacheFile(const Scene& scene, const RenderSettings& settings,
                                               const std::shared_ptr<IrradianceCache>& cache);

class PersistentCache {
public:
    // Opens (or creates) `path` for this scene and these settings, and loads its records into `cache`.
    // Throws Error when the file belongs to another scene or other options, or is damaged.
    PersistentCache(const std::string& path, const Scene& scene, const RenderSettings& settings,
                    std::shared_ptr<IrradianceCache> cache);
    // Appends the records made since the last call, and loads those other processes appended meanwhile.
    // Not while the cache is in use.
    void sync();

private:
    void load();
    CacheFile file_;
    std::shared_ptr<IrradianceCache> cache_;
    size_t known_ = 0;  // records [0, known_) are in the file
};

}  // namespace brume
