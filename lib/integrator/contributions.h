// Contributions (Radiance's rcontrib): which part of a query's value each light source's emission brings,
// told source sample by source sample as the paths find them. A path carries its throughput forward
// (PathState::throughput: what a unit of radiance along the ray adds to the query's value), and wherever
// light is emitted into the value — a source a ray meets (with its multiple-importance share), a shadow ray's
// sample (a uniform source's closed form on a diffuse surface: once, from the source's centre), a sample aimed
// at the sky through a window or at a sunlit patch — the sink hears of the source's
// modifier, the ray toward it, and the coefficient its radiance is multiplied by. Over one query the
// coefficients times the radiances sum to the value the integrator returns.
#pragma once
#include <limits>

#include "integrator/path_context.h"
#include "integrator/path_state.h"

namespace brume {

struct Contribution {
    int modifier;                // the object the emitting surface's modifier chain starts from
    dvec3 origin, dir;           // the ray that found the source: where from, and toward it (unit)
    double distance;             // to the source along it (infinity for sources at infinity)
    dvec3 point, normal;         // where it met the source (for sources at infinity: far along the ray, -dir)
    const Spectrum& coefficient;  // what the source's radiance is multiplied by to give its part of the value
    const Spectrum& radiance;     // the source's radiance toward the ray (its pattern applied)
};

class ContributionSink {
public:
    virtual void add(const Contribution& c) = 0;

protected:
    ~ContributionSink() = default;
};

// A child ray's throughput: its parent's times `factor` (a Spectrum or a float), kept in `storage`, which must
// outlive the child's tracing. Nothing where no one collects contributions.
template <class Factor>
void carryThroughput(const PathState& parent, PathState& child, const Factor& factor, Spectrum& storage) {
    if (!parent.throughput) return;
    storage = *parent.throughput * factor;
    child.throughput = &storage;
}

// Tells the sink (if any) that emission of radiance `le` from the source of `modifier`, met `distance` along
// the ray from `origin` in direction `dir`, adds state's throughput × `factor` × le to the value.
inline void contribute(PathContext& ctx, const PathState& state, int modifier, const dvec3& origin, const dvec3& dir,
                       double distance, const dvec3& normal, const Spectrum& factor, const Spectrum& le) {
    if (!ctx.contributions || !state.throughput) return;
    Spectrum coefficient = *state.throughput * factor;
    dvec3 point = std::isfinite(distance) ? origin + distance * dir : origin + integrator_detail::kDistantSourceDistance * dir;
    ctx.contributions->add(Contribution{modifier, origin, dir, distance, point, normal, coefficient, le});
}
inline void contribute(PathContext& ctx, const PathState& state, int modifier, const dvec3& origin, const dvec3& dir,
                       double distance, const dvec3& normal, float factor, const Spectrum& le) {
    if (!ctx.contributions || !state.throughput) return;
    contribute(ctx, state, modifier, origin, dir, distance, normal, Spectrum(factor, le.size()), le);
}

}  // namespace brume
