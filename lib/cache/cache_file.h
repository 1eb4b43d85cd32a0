// Irradiance cache files (-af): records kept between runs and shared by the threads and processes rendering
// one scene, as Radiance's ambient files are (but in Brume's own format, which Radiance's tools do not read).
//
// A text header, ended by an empty line:
//     #?BRUME_IRRADIANCE_CACHE
//     FORMAT=brume_irradiance_cache 4
//     SCENE=<sceneContentHash>
//     OPTIONS=<every option that changes cached values>
//     CHANNELS=<spectrum channels per value>
// then blocks, each appended whole by one writer: a 16-byte head (a tag naming the kind of its records, the
// record count, the CRC-32 of the records, the CRC-32 of the head's first 12 bytes) and the records. Surface
// records ("SURF"): point, normal, axis as 3 doubles each (positions round-trip exactly), the time as 4
// doubles (RecordTime: the instant, the window's start and end, the spacing of its records), the two radii as
// floats, the level as a 32-bit integer, then CHANNELS × 5 floats of values. All
// numbers are little-endian IEEE 754, as in memory on x86 and ARM. Volume records ("VOLU", whose head
// holds the records' size in bytes where a surface block's holds their count): point and time as 7
// doubles, the radius as a float, the level, the number of peaks P and how many of the last are the sources'
// as 32-bit integers, CHANNELS × 36 floats of coefficients and gradients, then per peak 4 floats (direction,
// inverse distance), then P × CHANNELS floats of the peaks' light. Formats 1 (records without an instant), 2
// (volume records without the sources' light) and 3 (records of one instant, without a window) are refused.
#pragma once
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "cache/surface_record.h"
#include "cache/volume_record.h"

namespace brume {

// What a cache file's records are valid for: values from another scene or other options are never reused.
struct CacheIdentity {
    std::string scene;    // content hash of the scene (sceneContentHash, scene/scene_hash.h)
    std::string options;  // canonical text of every option that changes cached values, e.g. "-ab 5 -aa 0.1 -ad 1024"
    int channels = 3;     // spectrum channels per value
};

// A cache file shared by threads (one object, its calls serialised) and by processes (each with its own
// object; blocks are appended under an exclusive lock on the file, so writers interleave nothing).
class CacheFile {
public:
    // Opens `path`, creating it with `identity`'s header if it does not exist or is empty. Throws Error when
    // the file cannot be opened, was made for another scene, other options or another channel count (saying
    // which), or is not a cache file.
    CacheFile(std::string path, CacheIdentity identity);
    CacheFile(const CacheFile&) = delete;
    CacheFile& operator=(const CacheFile&) = delete;
    ~CacheFile();

    // The records appended to the file since the last call, by other objects or processes (those appended
    // through this object are not returned); the first call returns every record in the file. Throws Error
    // naming the file and byte offset of a corrupted block or an invalid record. A last block that a writer
    // left incomplete (it died mid-append) is dropped with a warning and cut from the file.
    std::vector<SurfaceRecord> readNew();
    // The same for volume records.
    std::vector<VolumeRecord> readNewVolumes();
    // Appends the records as one block, written with one write and synced before the lock is released.
    // Records must have `channels` values of each field and be valid (finite, unit normal and axis, positive
    // radii), else std::invalid_argument. Throws Error when the file cannot be written (it is left as it was).
    void append(const std::vector<SurfaceRecord>& records);
    void append(const std::vector<VolumeRecord>& records);

    const std::string& path() const { return path_; }

private:
    // Reads the blocks added after offset_ into unread_ and unreadVolumes_, under the file lock.
    void catchUp();
    void readSurfaces(const std::string& records, uint32_t count);
    void readVolumes(const std::string& records);
    // Writes a whole block (head and records) at the end of the file, under the file lock.
    void appendBlock(const std::string& block);
    void checkHeader();

    std::string path_;
    CacheIdentity identity_;
    int fd_ = -1;
    size_t recordSize_;
    std::mutex mutex_;
    uint64_t offset_ = 0;  // where the first block not yet read starts
    std::vector<SurfaceRecord> unread_;
    std::vector<VolumeRecord> unreadVolumes_;
};

}  // namespace brume
