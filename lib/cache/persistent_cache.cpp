#include "cache/persistent_cache.h"

namespace brume {

PersistentCache::PersistentCache(const std::string& path, const CacheIdentity& identity, SurfaceCache& cache)
    : file_(path, identity), cache_(cache) {
    load();
}

void PersistentCache::load() {
    std::vector<SurfaceRecord> records = file_.readNew();
    if (!records.empty()) cache_.insertSaved(std::move(records));
}

void PersistentCache::sync() {
    std::vector<SurfaceRecord> made = cache_.takeUnsaved();
    if (!made.empty()) file_.append(made);
    load();
}

}  // namespace brume
