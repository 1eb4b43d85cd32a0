// What the cache-file fuzzer and the corpus replay do with an input: the bytes as an irradiance cache
// file (made for the scene and options "fuzz", 3 channels), loaded; every record it yields (surface and
// volume records) must be valid.
#pragma once
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "cache/cache_file.h"
#include "util/error.h"

namespace brume {

inline bool exerciseCacheFile(std::string_view bytes) {
    namespace fs = std::filesystem;
    fs::path path = fs::temp_directory_path() / ("brume_fuzz_cache_" + std::to_string(getpid()));
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    bool valid = true;
    try {
        CacheFile file(path.string(), CacheIdentity{"fuzz", "fuzz", 3});
        for (const SurfaceRecord& r : file.readNew()) {
            valid = valid && r.channels() == 3 && r.radius[0] > 0 && r.radius[1] > 0 && r.level >= 0 &&
                    std::abs(glm::length(r.normal) - 1) < 1e-3;
            for (float v : r.values) valid = valid && std::isfinite(v);
        }
        for (const VolumeRecord& r : file.readNewVolumes()) {
            valid = valid && r.channels() == 3 && r.radius > 0 && r.level >= 0 &&
                    r.peakFlux.size() == size_t(3 * r.peaks());
            for (const glm::vec4& ray : r.peakRays) valid = valid && std::abs(glm::length(glm::vec3(ray)) - 1) < 1e-3f;
            for (float v : r.values) valid = valid && std::isfinite(v);
            for (float v : r.peakFlux) valid = valid && std::isfinite(v);
        }
    } catch (const Error&) {
    }
    fs::remove(path);
    return valid;
}

}  // namespace brume
