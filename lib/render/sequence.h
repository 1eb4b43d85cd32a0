// The work of one run, in order — rtrace's batches of rays, rpict's frames, mkcache's points or picture —
// served by one integrator and, with -ab and -aa > 0, one irradiance cache (and its -af file) and one volume
// cache (records in media), whose records serve every later item at their instant.
//
// With the cache, work items run in passes (build, then render): every pass looks records up in a cache that
// does not change while it runs; an item that found no record where it needed one runs again in the next
// pass, after the records asked for are made. Records are made in an order fixed by the items' order, not by
// the threads, so results do not depend on -n.
#pragma once
#include <functional>
#include <memory>

#include <tbb/enumerable_thread_specific.h>

#include "cache/persistent_cache.h"
#include "cache/surface_cache.h"
#include "cache/volume_cache.h"
#include "integrator/integrator.h"
#include "render/frames.h"
#include "render/picture_renderer.h"

namespace brume {

class ProgressMeter;

// The cache's record shape for a scene: -acache, -aa, and radius bounds from the scene's size and -ar.
RecordShape recordShape(const RenderScene& scene, const RenderSettings& settings);

class Sequence {
public:
    // Makes the cache the settings call for and opens their -af file (Error if it belongs to another scene
    // or other options); `scene` is the one `renderScene` was compiled from.
    Sequence(const Scene& scene, const RenderScene& renderScene, const RenderSettings& settings);

    const Integrator& integrator() const { return integrator_; }
    // The irradiance cache, or null when -ab, -aa or -ad is 0.
    const SurfaceCache* cache() const { return cache_.get(); }
    // The volume cache, there whenever the irradiance cache is (it holds records only where media scatter).
    const VolumeCache* volumes() const { return volumes_.get(); }

    // Runs work items 0 … count-1 at instant `time` on all threads, each given its thread's scratch and its
    // cache visit, in passes as the cache needs them; then appends the records made to the -af file.
    void run(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item);
    // The same for a part of a larger piece of work (a picture's band of rows), whose records go to the -af
    // file when the whole is done.
    void runPart(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item);
    // Runs work items without the cache, each sampling its paths itself (shared bounces: records would not
    // carry their throughputs).
    void runPaths(size_t count, double time, const std::function<void(size_t, WorkItem&)>& item);
    // How many records' light the run has traced so far (a window's: two or more, RecordWindows).
    uint64_t tracedRecords() const { return tracedRecords_; }
    // A frame's picture. Each frame's passes are numbered from the first, as if it were alone: its records
    // are seeded by where its pixels lie, not by the frames before it.
    RenderedPicture render(const SequenceFrame& frame, const PictureSettings& settings, ProgressMeter* progress);

private:
    void moveTo(double time);
    // Makes the records these requests call for, each in its cache (surface requests have a normal), and
    // those their own rays ask for.
    void makeRecords(const std::vector<RecordRequest>& requests);

    std::unique_ptr<SurfaceCache> cache_;
    std::unique_ptr<VolumeCache> volumes_;
    Integrator integrator_;
    std::unique_ptr<PersistentCache> cacheFile_;
    tbb::enumerable_thread_specific<Scratch> scratch_;
    uint64_t passes_ = 0;  // run so far: they seed the records their items ask for
    uint64_t tracedRecords_ = 0;
};

}  // namespace brume
