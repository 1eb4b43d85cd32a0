// Shared bounces (rcontrib's and rfluxmtx's -aS, rtrace's for sensors): the continuations past the first bounce
// of a batch's paths, pooled between nearby first hits. A sensor's -ad rays meet the room at thousands of
// points; the light each point gathers from the rest of the scene past its own direct light (its
// continuation) changes slowly across a surface, yet one path a point estimates it. Here the points of a
// batch are grouped into cells (one scene object, a cube of side 2^⌊log₂(relativeSize × distance)⌋ where
// distance is the point's from the query that found it, so that from there a cell looks about as large at
// any scale of the model, and a cone of normals of ≈ 11°); a cell traces a few continuations from points
// spread over it, and each point takes the cell's mean, times its own throughput. Fewer deep paths, each
// shared by many points: the noise of the deep bounces falls with the cell's count rather than with one path
// per point, at the cost of a bias, the cell's blur of a smooth function (second order in its size on a
// plane). Each point's direct light, sky through windows and sun patches stay its own.
#pragma once
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "integrator/deferred_bounces.h"
#include "io/ray_record.h"

namespace brume {

class Integrator;
class OptionTable;
class RenderScene;
class Sequence;
struct RenderSettings;
struct WorkItem;

// -aS frac: first bounces within this fraction of their distance share continuations; 0 none (rtrace,
// rcontrib, rfluxmtx).
constexpr double kShareBouncesDefault = 0.125;
void addShareBouncesOption(OptionTable& table, double& fraction);
// Whether sensors' bounces can be shared in this scene with these settings: bounces past the first, and no
// media (paths through them carry no throughput).
bool sharesBounces(const RenderScene& scene, const RenderSettings& settings);

// First bounces a batch keeps (≈ 70 bytes each) until its cells are traced; batches are cut to fit.
constexpr size_t kSharedBouncesPerBatch = size_t(1) << 21;
// Continuations a cell traces at most where the queries send `ambientDivisions` (-ad) rays: 32, or one for
// every 32 of their rays, so that more -ad lowers the cells' noise with the points' own (bench/annual.py,
// bench/point_in_time.py).
int continuationsPerCell(int ambientDivisions);

// One continuation a cell traces: from `bounce` along unit `dir`, standing for `weightScale` first hits,
// its samples seeded by `index`.
struct Continuation {
    const DeferredBounce* bounce;
    dvec3 dir;
    double weightScale;
    uint64_t index;
};

class SharedBounces {
public:
    // What a cell's continuations bring, traced by the caller and summed into `sums` (its width: a record's).
    using CellTracer = std::function<void(const std::vector<Continuation>&, WorkItem&, std::vector<double>& sums)>;

    // `width`: the numbers a record sums (rcontrib: bins × channels; rtrace: channels); the throughputs
    // have `channels` components, the w-th number taking the (w mod channels)-th.
    // `origin`: where the cells' cubes are counted from (the scene's, SceneGeometry::origin), so that a model at
    // its site's coordinates has the cells it has at (0, 0, 0).
    SharedBounces(double relativeSize, int perCell, int channels, size_t width, const dvec3& origin);

    // Forgets the last batch; sinks for `records` records.
    void reset(size_t records);
    BounceSink& of(size_t record) { return records_[record]; }
    // Traces every cell's continuations (perCell at most, spread over its points and its
    // hemisphere) at `time` through `sequence` (without the cache) and `trace`, and adds to each record's
    // sums `scale` × its points' throughputs times their cells' means. `first` seeds the cells' samples.
    void resolve(Sequence& sequence, double time, uint64_t first, const CellTracer& trace, double scale,
                 std::vector<std::vector<double>>& sums) const;
    // The same for rtrace's values: continuations' radiance, added to each record's value.
    void resolveValues(Sequence& sequence, const Integrator& integrator, double time, uint64_t first,
                       std::vector<RayRecord>& records) const;

private:
    struct Key {
        int object, level, x, y, z, normal;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const;
    };
    struct Record final : BounceSink {
        SharedBounces* owner = nullptr;
        std::vector<DeferredBounce> bounces;
        std::vector<int> slotOf;                     // each bounce's cell's slot
        std::unordered_map<Key, int, KeyHash> slot;  // a cell's place in slotKeys and throughputs
        std::vector<Key> slotKeys;
        std::vector<float> throughputs;  // per slot, channels sums
        void defer(const DeferredBounce& bounce, const Spectrum& throughput) override;
    };
    struct Cells {
        std::unordered_map<Key, int, KeyHash> index;           // a cell's place in hits
        std::vector<std::vector<const DeferredBounce*>> hits;  // each cell's, in order of arrival
    };
    Key keyOf(const DeferredBounce& b) const;
    Cells cells() const;
    static std::vector<Continuation> continuations(const std::vector<const DeferredBounce*>& hits, int perCell,
                                                   uint64_t index);

    double relativeSize_;
    int perCell_, channels_;
    size_t width_;
    dvec3 origin_;
    std::vector<Record> records_;
};

}  // namespace brume
