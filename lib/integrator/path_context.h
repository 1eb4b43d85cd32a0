// What the rays of one work item (a ray given on input, a pixel, a sensor, a cache record) share as they are
// traced: the random stream its seed starts, its thread's scratch, the instant it is traced at and the
// smoke then, the cache visit that notes the records its lookups miss, and where its outputs and its sources'
// contributions go.
#pragma once
#include "cache/record_passes.h"
#include "integrator/ray_outputs.h"
#include "integrator/scratch.h"
#include "medium/participating_media.h"
#include "sampling/random.h"

namespace brume {

class ContributionSink;
class BounceSink;

struct PathContext {
    Random rng;
    Scratch& scratch;
    double time;                      // the scene's instant (s)
    const ParticipatingMedia& smoke;  // the smoke at that instant
    CacheVisit* visit = nullptr;      // null: no cache lookups (paths sample what records would give)
    RayOutputs* outputs = nullptr;    // null: nobody asks for rtrace's outputs
    ContributionSink* contributions = nullptr;  // null: nobody asks which source brings what (contributions.h)
    BounceSink* bounces = nullptr;  // non-null: first bounces hand their continuations there (deferred_bounces.h)

    // The outputs, where the record of the ray being traced is asked for (else null).
    RayOutputs* recording() const { return outputs && outputs->record() ? outputs : nullptr; }
};

// Seeds from the run's (fixed by -u-, else new each run): of the samples of work item `index`, and of the
// record requests of pass `pass` of a loop over work items.
struct Seeds {
    uint64_t run;
    uint64_t of(uint64_t index) const { return mixBits(run ^ mixBits(index + 0x9e3779b97f4a7c15ULL)); }
    uint64_t ofPass(uint64_t pass) const { return mixBits(run ^ (0x51ed270b7a3cULL + pass)); }
};

}  // namespace brume
