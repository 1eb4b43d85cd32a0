#include "integrator/persistent_cache.h"

#include "integrator/render_options.h"
#include "scene/scene_hash.h"
#include "util/error.h"

namespace brume {

std::string cacheOptions(const RenderSettings& settings) {
    RenderSettings copy = settings;
    bool irradianceAtHit = false;
    OptionTable table;
    addRenderOptions(table, copy, irradianceAtHit);
    std::string text = "brume-" BRUME_VERSION;
    for (const std::string& option : table.valueOptions()) {
        // Which surface a value is asked for (-i) and how samples are seeded (-u) change no record.
        if (option.rfind("-i", 0) == 0 || option.rfind("-u", 0) == 0 || option.rfind("-af", 0) == 0) continue;
        text += " " + option;
    }
    return text;
}

std::unique_ptr<PersistentCache> openCacheFile(const Scene& scene, const RenderSettings& settings,
                                               const std::shared_ptr<IrradianceCache>& cache) {
    if (settings.cacheFile.empty()) return nullptr;
    if (cache) return std::make_unique<PersistentCache>(settings.cacheFile, scene, settings, cache);
    warn("-af " + settings.cacheFile + " ignored: there is no irradiance cache without -ab > 0 and -aa > 0");
    return nullptr;
}

PersistentCache::PersistentCache(const std::string& path, const Scene& scene, const RenderSettings& settings,
                                 std::shared_ptr<IrradianceCache> cache)
    : file_(path, CacheIdentity{sceneContentHash(scene), cacheOptions(settings), Spectrum::defaultChannels()}),
      cache_(std::move(cache)) {
    load();
}

void PersistentCache::load() {
    std::vector<IrradianceRecord> records = file_.readNew();
    if (!records.empty()) cache_->insert(std::move(records));
    known_ = cache_->size();
}

void PersistentCache::sync() {
    if (cache_->size() > known_) {
        std::vector<IrradianceRecord> made;
        for (size_t i = known_; i < cache_->size(); ++i) made.push_back(cache_->record(i));
        file_.append(made);
    }
    load();
}

}  // namespace brume
