// Shared bounces (rcontrib, rfluxmtx): the continuations past the first bounce of a batch's paths, pooled
// between nearby first hits. A sensor's -ad rays meet the room at thousands of points; the light each
// point gathers from the rest of the scene past its own direct light (its continuation) changes slowly
// across a surface, yet one path a point estimates it. Here the points of a batch are grouped into cells
// (one scene object, a cube of side `cellSize`, a narrow cone of normals); a cell traces a few
// continuations from points spread over it, and each point takes the cell's mean coefficients, times its
// own throughput. Fewer deep paths, each shared by many points: the noise of the deep bounces falls with
// the cell's count rather than with one path per point, at the cost of a bias, the cell's blur of a smooth
// function (second order in cellSize on a plane). Each point's direct light, sky through windows and sun
// patches stay its own.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "contrib/contribution_tally.h"
#include "integrator/deferred_bounces.h"

namespace brume {

class Integrator;
class Sequence;
struct WorkItem;

// First bounces a batch keeps (≈ 70 bytes each) until its cells are traced; rcontrib's batches are cut to fit.
constexpr size_t kSharedBouncesPerBatch = size_t(1) << 21;
// Continuations a cell traces at most: past some tens, the noise left is that of each point's own direct
// light, not the cells' (bench/annual.py).
constexpr int kContinuationsPerCell = 32;

class SharedBounces {
public:
    // Cells of side 2^⌊log₂(relativeSize × distance)⌋, the distance of a point from the query that found it,
    // so that from there a cell looks about as large wherever it is, at any scale of the model.
    SharedBounces(double relativeSize, int channels);

    // Forgets the last batch; sinks for `records` records.
    void reset(size_t records);
    BounceSink& of(size_t record) { return records_[record]; }
    // Traces every cell's continuations (kContinuationsPerCell at most, spread over its points and its
    // hemisphere) at `time` through `sequence`, and adds to each record's sums (columns × channels) `scale` ×
    // its points' throughputs times their cells' mean coefficients. `first` seeds the cells' samples. Returns
    // the contributions ignored for bins past the last.
    long resolve(Sequence& sequence, const Integrator& integrator, double time, uint64_t first,
                 const ModifierBins& bins, bool values, double scale, std::vector<std::vector<double>>& sums) const;

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
        std::unordered_map<Key, int, KeyHash> index;             // a cell's place in hits
        std::vector<std::vector<const DeferredBounce*>> hits;  // each cell's, in order of arrival
    };
    Key keyOf(const DeferredBounce& b) const;
    Cells cells() const;
    void traceCell(const std::vector<const DeferredBounce*>& hits, uint64_t index, double time,
                   const Integrator& integrator, WorkItem& item, ContributionTally& tally,
                   std::vector<std::pair<uint32_t, float>>& mean) const;

    double relativeSize_;
    int channels_;
    std::vector<Record> records_;
};

}  // namespace brume
