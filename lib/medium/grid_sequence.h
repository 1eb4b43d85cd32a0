// Smoke that evolves in time: density grids at key instants (a fire simulation's output frames), linearly
// interpolated in between (Ribardière 2010: key and intermediate instants).
#pragma once
#include <vector>

#include "medium/density_grid.h"
#include "medium/majorant_grid.h"

namespace brume {

struct KeyFrame {
    double time;  // seconds
    DensityGrid grid;
};

class GridSequence {
public:
    // Frames in any order (they are sorted by time); Error if there is none or two share a time (the
    // message names no source: the caller says whose frames they are).
    explicit GridSequence(std::vector<KeyFrame> frames);

    // Linear in time between the key frames around `time`; the first or last frame's density outside them
    // (SmokeVolume refuses such instants: none reaches a run).
    double density(const dvec3& p, double time) const;
    // ∫ density(ray.at(t), time) dt over [t0, t1], exactly (DensityGrid::integral).
    double integral(const Ray& ray, double t0, double t1, double time) const;
    // The density along the ray over [t0, t1] at `time`, cell by cell (DensityGrid::profile, blended).
    DensityProfile profile(const Ray& ray, double t0, double t1, double time) const;
    // Where any frame's density can be non-zero.
    Bounds3 bounds() const;
    // The length of [t0, t1] along the ray in the domain of a simulation and without its data at `time`: the
    // longer of the two key frames' around it (DataCoverage).
    double uncoveredLength(const Ray& ray, double t0, double t1, double time) const;
    // Bounds the density at every time in [t0, t1]: the majorants of the key frames from the last at or
    // before t0 to the first at or after t1 (linear interpolation never exceeds its two ends). Built on
    // each call (a pass over those frames' active voxels): keep it for the frame or interval it serves.
    MajorantGrid majorant(double t0, double t1, int voxelsPerCell = 8) const;

    // Bounds of the density at the one instant `time`: the key frames around it, weighted as density() weighs
    // them (tighter than majorant(time, time), which bounds the whole interval between them).
    MajorantGrid boundsAt(double time, int voxelsPerCell = 8) const;

    const std::vector<KeyFrame>& keyFrames() const { return frames_; }

private:
    // density(p, time) = (1 − w)·frames_[before] + w·frames_[later].
    struct Blend {
        std::size_t before, later;
        double w;
    };
    Blend blendAt(double time) const;

    std::vector<KeyFrame> frames_;
};

}  // namespace brume
