// Everything on the command line that changes computed values (the -a, -d, -l, -s, -b and -u options).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "cache/record_shape.h"
#include "material/material.h"
#include "medium/homogeneous_medium.h"
#include "spectrum/spectral_sampling.h"
#include "spectrum/spectrum.h"

namespace brume {

struct RenderSettings {
    int ambientBounces = 0;          // -ab: diffuse interreflections (past them: bounceTail)
    bool ambientLimit = false;       // -al+: with the cache too, nothing past -ab bounces (Radiance's numbers)
    int ambientDivisions = 1024;     // -ad: paths per shading point at the first bounce
    int ambientSupersamples = 512;   // -as: Radiance's extra samples (Brume's records adapt otherwise: no effect)
    double ambientAccuracy = 0.1;    // -aa: the irradiance cache's relative error (0: no cache, path tracing)
    int ambientResolution = 256;     // -ar: the scene's size over the smallest record radius
    bool skyPortals = true;          // -aP: path-traced diffuse light aims at the sky through windows too
    RecordShape::Kind cacheKind = RecordShape::Kind::Adaptive;  // -acache adaptive|classic
    std::string cacheFile;           // -af: where the cache's records are kept between runs (changes no value)
    double recordLifetime = 32;      // -at: the longest window of time a record serves (s; 0: its instant alone)
    int ambientWeight = 0;           // -aw (Radiance's weight of -av in its records: no effect)
    double photonSearchRadius = 0;   // -am (no photon maps: no effect)
    Spectrum ambientValue{0.f};      // -av: radiance assumed beyond the last bounce (RGB as given; see inBands)
    int maxReflections = -10;        // -lr: > 0 hard limit; ≤ 0 Russian roulette past |lr| reflections
    double minWeight = 1e-4;         // -lw: rays below this weight are played by Russian roulette
    double sourceSubdivision = 0.2;  // -ds: more shadow rays for sources larger than this, seen from a point
    double sourceJitter = 0;         // -dj (sources are always sampled stratified; kept for compatibility)
    double directThreshold = 0.03;   // -dt: fewer shadow rays to sources with a smaller share of the light
    double directCertainty = 0.75;   // -dc (every shadow ray is traced: no effect)
    int directRelays = 2;            // -dr: sources seen through flat mirrors
    int directPresamples = 512;      // -dp (no presampling: no effect)
    bool directVisible = true;       // -dv: light sources seen by rays
    double specularJitter = 1;       // -ss (lobes are always sampled: no effect)
    MaterialSettings materials;      // -st, -bv
    bool randomSampling = true;      // -u: a new seed each run; -u- a fixed one
    uint64_t seed = 0;               // used when -u-
    SpectralSampling sampling;       // -cs, -cw
    std::optional<double> time;      // -T: the scene's instant (s), for smoke that evolves in time
    HomogeneousMedium medium;        // -me, -ma (RGB as given; see inBands), -mg
    double mediumSampling = 0;       // -ms: spacing of in-scattering samples along a ray (0: one per ray)
    int majorantCell = 8;            // -mc: smoke majorant cells, in voxels (0: one for the whole grid)

    // Whether the irradiance cache is asked for: -ab, -aa and -ad positive.
    bool usesCache() const { return ambientBounces > 0 && ambientAccuracy > 0 && ambientDivisions > 0; }
    // With -aa > 0 (the irradiance cache) a Radiance user's typical call, -ab of a few bounces, means the
    // light of every bounce: paths past the -ab-th go on by Russian roulette, unbiased, one path each (a
    // decided difference: Radiance's cache stops there). -av gives them a value instead, and -al+ stops them
    // as Radiance does, so that a study can be checked against Radiance's numbers.
    bool bounceTail() const {
        return ambientAccuracy > 0 && ambientBounces > 0 && ambientValue.isBlack() && !ambientLimit;
    }
};

// The settings as light transport uses them: the colours given in RGB (-av, -me, -ma) lifted to the
// sampling's bands (smooth spectra; greys stay flat).
RenderSettings inBands(RenderSettings settings);
// The seed a run's samples start from: -u-'s, or one of its own for each run (-u+).
uint64_t runSeed(const RenderSettings& settings);

}  // namespace brume
