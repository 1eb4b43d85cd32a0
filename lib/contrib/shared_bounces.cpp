#include "contrib/shared_bounces.h"

#include <algorithm>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>

#include "integrator/integrator.h"
#include "render/sequence.h"
#include "sampling/warp.h"

namespace brume {

namespace {
constexpr int kNormalDivisions = 8;  // per face of the cube of normals: cells of ≈ 11°
}

SharedBounces::SharedBounces(double relativeSize, int channels) : relativeSize_(relativeSize), channels_(channels) {}

void SharedBounces::reset(size_t records) {
    records_.assign(records, Record{});
    for (Record& r : records_) r.owner = this;
}

size_t SharedBounces::KeyHash::operator()(const Key& k) const {
    uint64_t h = mixBits(uint64_t(uint32_t(k.object)) ^ (uint64_t(uint32_t(k.x)) << 32) ^ (uint64_t(k.level) << 20));
    h = mixBits(h ^ uint64_t(uint32_t(k.y)) ^ (uint64_t(uint32_t(k.z)) << 32));
    return size_t(mixBits(h ^ uint64_t(k.normal)));
}

// The cell of a point: its object, its cube, and its normal's cell on the cube of directions.
SharedBounces::Key SharedBounces::keyOf(const DeferredBounce& b) const {
    dvec3 n(b.normal);
    int axis = std::abs(n.x) >= std::abs(n.y) && std::abs(n.x) >= std::abs(n.z) ? 0 : std::abs(n.y) >= std::abs(n.z) ? 1 : 2;
    double major = std::abs(n[axis]);
    auto cell = [&](double c) { return std::clamp(int((c / major + 1) / 2 * kNormalDivisions), 0, kNormalDivisions - 1); };
    int face = 2 * axis + (n[axis] < 0);
    int normal = (face * kNormalDivisions + cell(n[(axis + 1) % 3])) * kNormalDivisions + cell(n[(axis + 2) % 3]);
    int level = std::ilogb(std::max(double(b.distance) * relativeSize_, 1e-30));
    auto at = [&](double c) { return int(std::clamp(std::floor(std::ldexp(c, -level)), -2e9, 2e9)); };
    return Key{b.object, level, at(b.point.x), at(b.point.y), at(b.point.z), normal};
}

void SharedBounces::Record::defer(const DeferredBounce& bounce, const Spectrum& throughput) {
    Key key = owner->keyOf(bounce);
    auto [it, added] = slot.try_emplace(key, int(slotKeys.size()));
    if (added) {
        slotKeys.push_back(key);
        throughputs.resize(throughputs.size() + owner->channels_, 0.f);
    }
    float* t = &throughputs[size_t(it->second) * owner->channels_];
    for (int c = 0; c < owner->channels_; ++c) t[c] += throughput[c];
    bounces.push_back(bounce);
    slotOf.push_back(it->second);
}

// The batch's cells in the order their first hits came (records in input order): the same on any thread count.
SharedBounces::Cells SharedBounces::cells() const {
    Cells cells;
    for (const Record& r : records_)
        for (size_t b = 0; b < r.bounces.size(); ++b) {
            auto [it, added] = cells.index.try_emplace(r.slotKeys[r.slotOf[b]], int(cells.hits.size()));
            if (added) cells.hits.emplace_back();
            cells.hits[it->second].push_back(&r.bounces[b]);
        }
    return cells;
}

// A cell's mean coefficients over k continuations from hits spread over it (in their order of arrival), their
// directions spread over the hemisphere (a scrambled Sobol' sequence), each standing for n/k hits.
void SharedBounces::traceCell(const std::vector<const DeferredBounce*>& hits, uint64_t index, double time,
                              const Integrator& integrator, WorkItem& item, ContributionTally& tally,
                              std::vector<std::pair<uint32_t, float>>& mean) const {
    tally.clear();
    WorkItem told{item.scratch, nullptr, &tally};
    size_t n = hits.size(), k = std::min<size_t>(n, size_t(kContinuationsPerCell));
    uint64_t scramble = mixBits(index);
    for (size_t j = 0; j < k; ++j) {
        const DeferredBounce& b = *hits[(2 * j + 1) * n / (2 * k)];
        double u, v;
        sobol2D(uint32_t(j), scramble, u, v);
        dvec3 dir = Frame(dvec3(b.normal)).toWorld(cosineHemisphere(u, v));
        integrator.continueBounce(b, dir, time, double(n) / double(k), index + j, told);
    }
    const std::vector<double>& sums = tally.sums();
    for (size_t w = 0; w < sums.size(); ++w)
        if (sums[w] != 0) mean.emplace_back(uint32_t(w), float(sums[w] / double(k)));
}

long SharedBounces::resolve(Sequence& sequence, const Integrator& integrator, double time, uint64_t first,
                            const ModifierBins& bins, bool values, double scale,
                            std::vector<std::vector<double>>& sums) const {
    Cells cells = this->cells();
    std::vector<std::vector<std::pair<uint32_t, float>>> means(cells.hits.size());  // each cell's nonzero bins
    tbb::enumerable_thread_specific<ContributionTally> tallies([&] { return ContributionTally(bins, values, channels_); });
    // Seeds apart from the records' (whose indices count rays from 0).
    uint64_t batch = (uint64_t(1) << 63) | mixBits(first ^ 0x5ba7ed0b0c3cULL);
    sequence.run(cells.hits.size(), time, [&](size_t c, WorkItem& item) {
        traceCell(cells.hits[c], mixBits(batch + c) | (uint64_t(1) << 63), time, integrator, item, tallies.local(), means[c]);
    });
    tbb::parallel_for(size_t(0), records_.size(), [&](size_t i) {
        const Record& r = records_[i];
        for (size_t s = 0; s < r.slotKeys.size(); ++s) {
            const float* t = &r.throughputs[s * channels_];
            for (auto [w, mean] : means[cells.index.at(r.slotKeys[s])]) sums[i][w] += scale * double(t[w % channels_]) * mean;
        }
    });
    long ignored = 0;
    for (const ContributionTally& t : tallies) ignored += t.outOfRange();
    return ignored;
}

}  // namespace brume
