#include "cache/persistent_cache.h"

namespace brume {

PersistentCache::PersistentCache(const std::string& path, const CacheIdentity& identity, SurfaceCache& cache,
                                 VolumeCache* volumes)
    : file_(path, identity), cache_(cache), volumes_(volumes) {
    load();
}

void PersistentCache::load() {
    std::vector<SurfaceRecord> records = file_.readNew();
    if (!records.empty()) cache_.insertSaved(std::move(records));
    std::vector<VolumeRecord> inMedia = file_.readNewVolumes();
    if (volumes_ && !inMedia.empty()) volumes_->insertSaved(std::move(inMedia));
}

void PersistentCache::sync() {
    file_.append(cache_.takeUnsaved());
    if (volumes_) file_.append(volumes_->takeUnsaved());
    load();
}

}  // namespace brume
