#include "medium/grid_sequence.h"

#include <algorithm>
#include <sstream>

#include "util/error.h"

namespace brume {

GridSequence::GridSequence(std::vector<KeyFrame> frames) : frames_(std::move(frames)) {
    if (frames_.empty()) throw Error("no key frame");
    std::ranges::stable_sort(frames_, {}, &KeyFrame::time);
    for (std::size_t i = 1; i < frames_.size(); ++i)
        if (frames_[i].time == frames_[i - 1].time)
            throw Error("two key frames at time " + (std::ostringstream() << frames_[i].time).str() + " s");
}

GridSequence::Blend GridSequence::blendAt(double time) const {
    // The first frame later than `time`.
    const auto later = std::ranges::upper_bound(frames_, time, {}, &KeyFrame::time);
    if (later == frames_.begin()) return {0, 0, 0.0};
    if (later == frames_.end()) return {frames_.size() - 1, frames_.size() - 1, 0.0};
    const std::size_t i = later - frames_.begin();
    return {i - 1, i, (time - frames_[i - 1].time) / (frames_[i].time - frames_[i - 1].time)};
}

double GridSequence::density(const dvec3& p, double time) const {
    const Blend b = blendAt(time);
    if (b.later == b.before) return frames_[b.before].grid.density(p);
    return (1 - b.w) * frames_[b.before].grid.density(p) + b.w * frames_[b.later].grid.density(p);
}

double GridSequence::integral(const Ray& ray, double t0, double t1, double time) const {
    const Blend b = blendAt(time);
    if (b.later == b.before) return frames_[b.before].grid.integral(ray, t0, t1);
    return (1 - b.w) * frames_[b.before].grid.integral(ray, t0, t1) + b.w * frames_[b.later].grid.integral(ray, t0, t1);
}

DensityProfile GridSequence::profile(const Ray& ray, double t0, double t1, double time) const {
    const Blend b = blendAt(time);
    DensityProfile before = frames_[b.before].grid.profile(ray, t0, t1);
    if (b.later == b.before) return before;
    return DensityProfile::sum(before, 1 - b.w, frames_[b.later].grid.profile(ray, t0, t1), b.w);
}

MajorantGrid GridSequence::boundsAt(double time, int voxelsPerCell) const {
    const Blend b = blendAt(time);
    if (b.later == b.before) return MajorantGrid(frames_[b.before].grid, voxelsPerCell);
    const DensityGrid grids[] = {frames_[b.before].grid, frames_[b.later].grid};
    const double weights[] = {1 - b.w, b.w};
    return MajorantGrid(grids, voxelsPerCell, weights);
}

double GridSequence::uncoveredLength(const Ray& ray, double t0, double t1, double time) const {
    const Blend b = blendAt(time);
    return std::max(frames_[b.before].grid.coverage().uncoveredLength(ray, t0, t1),
                    frames_[b.later].grid.coverage().uncoveredLength(ray, t0, t1));
}

Bounds3 GridSequence::bounds() const {
    Bounds3 b;
    for (const KeyFrame& frame : frames_) b.include(frame.grid.bounds());
    return b;
}

MajorantGrid GridSequence::majorant(double t0, double t1, int voxelsPerCell) const {
    // The last frame at or before t0 (else the first) to the first at or after t1 (else the last).
    const auto first = std::ranges::upper_bound(frames_, t0, {}, &KeyFrame::time);
    const auto last = std::ranges::lower_bound(frames_, t1, {}, &KeyFrame::time);
    const std::size_t i = first == frames_.begin() ? 0 : first - frames_.begin() - 1;
    const std::size_t j = last == frames_.end() ? frames_.size() - 1 : last - frames_.begin();
    std::vector<DensityGrid> grids;
    for (std::size_t k = i; k <= std::max(i, j); ++k) grids.push_back(frames_[k].grid);
    return MajorantGrid(grids, voxelsPerCell);
}

}  // namespace brume
