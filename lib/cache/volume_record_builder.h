// Volume records from sphere samples: the spherical-harmonic coefficients of the light arriving at the point,
// the peaks kept apart from them, their gradients, and the zone.
#pragma once
#include <limits>

#include "cache/record_shape.h"
#include "cache/source_samples.h"
#include "cache/sphere_samples.h"
#include "cache/volume_record.h"

namespace brume {

// The record of the light arriving at the samples' point, made for bounce `level`: of the light the sphere's
// rays found, the excess of the (at most 32) brightest samples over twice the median sample as peaks, the rest
// as harmonics; then each source's light (`sources`, one list of samples per source) as one to 36 peaks.
// Each sample is an equivalent point source where its ray met a surface (Jarosz et al. 2008's gradients for
// volume radiance caching take the same view), as each source's peak is at its distance: moving the point by
// δ changes its light by 2 ω·δ / d of itself, which gives the gradients (none from samples that met nothing).
// Adaptive zones size the second-order change the same sources make, their light's curvature averaged over
// the directions the point may move in (the Laplacian of 1/r², 2/r⁴, a third of the trace; a surface record
// bounds the largest, 6/r⁴, but a sphere's volume grows as r³, and lookups along a view ray average the
// errors of the records they cross), so that a first-order extrapolation errs by about ε Φ at the zone's
// edge: r = √(2 ε Φ / Σ 2 E_i/d_i²), then at most the distance over which the gradient would double or zero
// Φ. Classic zones: a sphere of radius ε R, R the samples' harmonic mean distance, clamped as surface
// records'. Either way at most √ε / (1 + √ε) times `nearestSource`, the distance D to the nearest lamp, so
// that the zone's edge is within √ε of its own distance to the lamp, r ≤ √ε (D − r) (the light lamps
// scatter in the medium around them, which a record holds, comes from about that far, not from the surfaces
// the rays met, and varies over that scale: as an equivalent point source of all the record's light there,
// 2Φ/D²; a zone sized by its centre's distance alone reached nearer the lamp, where lookups read its dimmer
// light), never past the nearest surface the rays met (a wall between the point and a lookup may hide a
// source from one and not the other), and at most ε / σ_t, σ_t the media's `extinction` at the point (moving
// by δ changes the transmittance toward every source by about e^(−σ_t δ), which no peak follows). The record's
// instant is the caller's to set.
VolumeRecord buildVolumeRecord(const SphereSamples& samples, const std::vector<SourceSamples>& sources,
                               const RecordShape& shape, int level,
                               double nearestSource = std::numeric_limits<double>::infinity(), double extinction = 0);

}  // namespace brume
