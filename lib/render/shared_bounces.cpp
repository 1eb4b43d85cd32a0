#include "render/shared_bounces.h"

#include <algorithm>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "integrator/integrator.h"
#include "render/sequence.h"
#include "sampling/warp.h"
#include "util/error.h"
#include "util/options.h"
#include "world/render_scene.h"

namespace brume {

namespace {
constexpr int kNormalDivisions = 8;  // per face of the cube of normals: cells of ≈ 11°
// Cubes start this fraction of their side off the origin's multiples: walls and floors lie at round distances from
// the origin, and on a cube's face rounding (at a site's coordinates) would tip their hits from cube to cube.
constexpr double kCubePhase = 0.3819660112501051;  // 2 − φ
}  // namespace

void addShareBouncesOption(OptionTable& table, double& fraction) {
    table.add("-aS", 1, "first bounces within this fraction of their distance share continuations (0: none)",
              [&fraction](const auto& a) {
                  fraction = toReal("-aS", a[0]);
                  if (!(fraction >= 0 && fraction <= 1)) throw Error("-aS: a fraction from 0 to 1 is expected");
              },
              [&fraction] { return formatReal(fraction); });
}

bool sharesBounces(const RenderScene& scene, const RenderSettings& settings) {
    return settings.ambientBounces >= 2 && settings.ambientDivisions > 0 && scene.smoke().empty() &&
           !scene.hasMists() && settings.medium.clear();
}

int continuationsPerCell(int ambientDivisions) { return std::max(32, ambientDivisions / 32); }

SharedBounces::SharedBounces(double relativeSize, int perCell, int channels, size_t width, const dvec3& origin)
    : relativeSize_(relativeSize), perCell_(perCell), channels_(channels), width_(width), origin_(origin) {}

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
    auto at = [&](double c) { return int(std::clamp(std::floor(std::ldexp(c, -level) + kCubePhase), -2e9, 2e9)); };
    dvec3 p = b.point - origin_;
    return Key{b.object, level, at(p.x), at(p.y), at(p.z), normal};
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

// k continuations from hits spread over a cell (in their order of arrival), their directions spread over the
// hemisphere (a scrambled Sobol' sequence), each standing for n/k hits.
std::vector<Continuation> SharedBounces::continuations(const std::vector<const DeferredBounce*>& hits, int perCell,
                                                       uint64_t index) {
    size_t n = hits.size(), k = std::min<size_t>(n, size_t(perCell));
    uint64_t scramble = mixBits(index);
    std::vector<Continuation> out;
    out.reserve(k);
    for (size_t j = 0; j < k; ++j) {
        const DeferredBounce* b = hits[(2 * j + 1) * n / (2 * k)];
        double u, v;
        sobol2D(uint32_t(j), scramble, u, v);
        out.push_back({b, Frame(dvec3(b->normal)).toWorld(cosineHemisphere(u, v)), double(n) / double(k), index + j});
    }
    return out;
}

void SharedBounces::resolve(Sequence& sequence, double time, uint64_t first, const CellTracer& trace, double scale,
                            std::vector<std::vector<double>>& sums) const {
    Cells cells = this->cells();
    std::vector<std::vector<std::pair<uint32_t, float>>> means(cells.hits.size());  // each cell's nonzero numbers
    tbb::enumerable_thread_specific<std::vector<double>> cellSums(width_, 0.0);
    // Seeds apart from the records' (whose indices count rays from 0).
    uint64_t batch = mixBits(first ^ 0x5ba7ed0b0c3cULL);
    sequence.runPaths(cells.hits.size(), time, [&](size_t c, WorkItem& item) {
        std::vector<Continuation> paths = continuations(cells.hits[c], perCell_, mixBits(batch + c) | (uint64_t(1) << 63));
        std::vector<double>& s = cellSums.local();
        std::fill(s.begin(), s.end(), 0.0);
        trace(paths, item, s);
        for (size_t w = 0; w < width_; ++w)
            if (s[w] != 0) means[c].emplace_back(uint32_t(w), float(s[w] / double(paths.size())));
    });
    tbb::parallel_for(size_t(0), records_.size(), [&](size_t i) {
        const Record& r = records_[i];
        for (size_t s = 0; s < r.slotKeys.size(); ++s) {
            const float* t = &r.throughputs[s * channels_];
            for (auto [w, mean] : means[cells.index.at(r.slotKeys[s])]) sums[i][w] += scale * double(t[w % channels_]) * mean;
        }
    });
}

void SharedBounces::resolveValues(Sequence& sequence, const Integrator& integrator, double time, uint64_t first,
                                  std::vector<RayRecord>& records) const {
    std::vector<std::vector<double>> sums(records.size(), std::vector<double>(width_, 0.0));
    resolve(sequence, time, first, [&](const std::vector<Continuation>& paths, WorkItem& item, std::vector<double>& s) {
        for (const Continuation& p : paths) {
            Spectrum v = integrator.continueBounce(*p.bounce, p.dir, time, p.weightScale, p.index, item);
            for (size_t c = 0; c < width_; ++c) s[c] += v[int(c)];
        }
    }, 1.0, sums);
    for (size_t i = 0; i < records.size(); ++i)
        for (size_t c = 0; c < width_; ++c) records[i].value[int(c)] += float(sums[i][c]);
}

}  // namespace brume
