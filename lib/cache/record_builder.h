// Irradiance records from hemisphere samples: the irradiance, its translational gradient (Ward & Heckbert
// 1992, occlusion-aware through the nearer of neighbouring cells), its rotational gradient, and the zone.
#pragma once
#include "cache/hemisphere_samples.h"
#include "cache/surface_record.h"
#include "cache/record_shape.h"

namespace brume {

// The record of indirect irradiance at the samples' point, made for diffuse bounce `level`.
//
// Adaptive zones (Ribardière 2010's, sized as Schwarzhaupt, Jensen & Jarosz 2012 bound the irradiance's
// Hessian): an occlusion-aware bound on the Hessian, summing every sample as an equivalent point source
// I = π L d² / (N cos θ) that may be an occluder's edge, gives the two axes (its eigenvectors) and their
// lengths r = √(2 ε E / λ), at which a first-order extrapolation errs by ε E. Each axis is then shortened
// until the extrapolation and the equivalent point sources' prediction at its ends agree within ε. Classic
// zones: a circle of radius ε R, R the harmonic mean distance of the samples (Ward's split sphere), as
// Radiance before its version 5. The record's instant is the caller's to set.
SurfaceRecord buildRecord(const HemisphereSamples& samples, const RecordShape& shape, int level);

}  // namespace brume
