#include "integrator/cache_client.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cache/hemisphere_samples.h"
#include "cache/record_builder.h"
#include "cache/sample_passes.h"
#include "cache/sphere_samples.h"
#include "cache/volume_record_builder.h"

namespace brume {

bool CacheClient::irradiance(const Receiver& at, const SurfaceId& surface, double pathWeight, const Spectrum& coef,
                             PathContext& ctx, Spectrum& value) const {
    if (!cache_ || !ctx.visit) return false;
    if (cache_->lookup(at, value)) return true;
    return waitsFor(at, surface, pathWeight, coef, ctx, value);
}

bool CacheClient::waitsFor(const Receiver& at, const SurfaceId& surface, double pathWeight, const Spectrum& coef,
                           PathContext& ctx, Spectrum& value) const {
    float weight = float(std::min(1.0, pathWeight * std::min(1.0, double(coef.maxValue()))));
    if (!ctx.visit->miss(at, surface, weight)) return false;
    value = Spectrum(0.f);
    return true;
}

bool CacheClient::inScattered(const Receiver& at, const dvec3& dir, const PhaseMixture& phase, bool sources,
                              double pathWeight, PathContext& ctx, Spectrum& value) const {
    if (!volumes_ || !ctx.visit) return false;
    Spectrum sum(0.f);
    const auto basis = shBasis(dir);
    double total = volumes_->gather(at, [&](const VolumeRecord& r, double w) {
        sum += VolumeZones::scattered(r, at.point, dir, basis, phase, sources) * float(w);
    });
    if (total > 0) {
        value = sum * float(1 / total);
        return true;
    }
    return waitsFor(at, SurfaceId{}, pathWeight, phase.coefficient(), ctx, value);
}

PathContext CacheClient::recordContext(const RecordRequest& q, Scratch& scratch, CacheVisit& visit,
                                       RayOutputs& outputs) const {
    return PathContext{Random(seeds_.of(q.key), q.key), scratch, q.at.time, media_.smokeAt(q.at.time), &visit, &outputs};
}

PathState CacheClient::recordRays(const RecordRequest& q, Scratch& scratch) const {
    PathState child = shading_.startingAt(q.at.point, scratch);
    child.kind = PathState::Kind::Sampled;
    child.ambientLevel = q.at.level + 1;
    child.reflections = q.at.level + 1;
    child.weight = q.weight;
    child.fromWeight = q.weight;
    child.depth = 1;
    return child;
}

double CacheClient::nearestSource(const dvec3& p) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Light& light : scene_.lights()) {
        if (light.isDistant() || !light.emitter().isDirectSource()) continue;
        double radius = 0.5 * light.size();
        nearest = std::min(nearest, std::max(glm::length(light.center() - p) - radius, radius));
    }
    return nearest;
}

double CacheClient::directIrradiance(const RecordRequest& q, const PathState& child, PathContext& ctx) const {
    const int count = std::max(2, recordDivisions(q) / (16 * std::max<int>(1, int(scene_.lights().size()))));
    double irradiance = 0;
    for (const Light& light : scene_.lights()) {
        SourceSamples arrived;
        lights_.arriving(light, q.at, q.leaving, count, child, ctx, arrived);
        for (const SourceSample& s : arrived) irradiance += brightness(s.flux) * glm::dot(*q.at.normal, s.dir);
    }
    return irradiance;
}

int CacheClient::passesFor(const HemisphereSamples& first, double known) const {
    double light = first.meanBrightness() + known;
    return light > 0 ? samplePasses(first.meanStandardError() / light, kNoiseShare * settings_.ambientAccuracy) : 1;
}

template <class Samples>
void CacheClient::tracePass(Samples& samples, int pass, const SurfaceId& leaving, const PathState& child,
                            PathContext& ctx) const {
    const dvec3& point = samples.point();
    for (int j = 0; j < samples.rows(); ++j) {
        for (int k = 0; k < samples.columns(); ++k) {
            dvec3 dir = samples.direction(j, k, ctx.rng.uniform(), ctx.rng.uniform());
            RayRecord hit;
            Spectrum l = tracer_.radiance(Ray{point, dir, std::numeric_limits<double>::infinity(), leaving}, child,
                                          ctx, nullptr, &hit);
            samples.set(samples.cell(j, k, pass), dir, l.clampFinite(), hit.firstLength);
        }
    }
}

namespace {
// The request at another instant.
RecordRequest at(RecordRequest q, double time) {
    q.at.time = time;
    return q;
}
}  // namespace

std::vector<SurfaceRecord> CacheClient::makeRecords(const RecordRequest& q, const OpenRecord<SurfaceRecord>* open,
                                                    Scratch& scratch, CacheVisit& visit) const {
    if (!open) return {windows_.recordAt(q.at.time, [&](double t) { return recordAt(at(q, t), scratch, visit); })};
    return windows_.windowFrom(open->record, cache_->kind(), settings_.ambientAccuracy,
                               [&](double t) { return recordAt(at(open->request, t), scratch, visit); });
}

std::vector<VolumeRecord> CacheClient::makeVolumeRecords(const RecordRequest& q, const OpenRecord<VolumeRecord>* open,
                                                         Scratch& scratch, CacheVisit& visit) const {
    if (!open)
        return {windows_.recordAt(q.at.time, [&](double t) { return volumeRecordAt(at(q, t), scratch, visit); })};
    return windows_.windowFrom(open->record, volumes_->kind(), settings_.ambientAccuracy,
                               [&](double t) { return volumeRecordAt(at(open->request, t), scratch, visit); });
}

SurfaceRecord CacheClient::recordAt(const RecordRequest& q, Scratch& scratch, CacheVisit& visit) const {
    ++visit.traced;
    RayOutputs outputs;
    PathContext ctx = recordContext(q, scratch, visit, outputs);
    const dvec3& point = q.at.point;
    HemisphereSamples samples(point, *q.at.normal, recordDivisions(q), Spectrum::defaultChannels());
    PathState child = recordRays(q, scratch);
    bool aims = portals_.active();
    aimingFrom(child, point, *q.at.normal, samples.strata(), aims);
    // Each pass aims as many samples as its strata ask for; the record takes their mean.
    std::vector<AimedSample> aimed;
    auto pass = [&](int p) {
        tracePass(samples, p, q.leaving, child, ctx);
        if (!aims) return;
        portals_.sample(point, *q.at.normal, q.leaving, samples.strata(), child, ctx, &aimed);
        patches_.sample(point, *q.at.normal, q.leaving, samples.strata(), child, ctx, &aimed);
    };
    pass(0);
    double aimedIrradiance = 0;
    for (const AimedSample& a : aimed) aimedIrradiance += brightness(a.irradiance);
    int passes = q.at.level > 0 ? 1
                                : passesFor(samples, (aimedIrradiance + directIrradiance(q, child, ctx)) / std::numbers::pi);
    for (int p = 1; p < passes; ++p) pass(samples.addPass());
    for (AimedSample& a : aimed) a.irradiance *= float(1.0 / passes);
    samples.aimed() = std::move(aimed);
    return buildRecord(samples, cache_->kind().shape(), q.at.level);
}

VolumeRecord CacheClient::volumeRecordAt(const RecordRequest& q, Scratch& scratch, CacheVisit& visit) const {
    ++visit.traced;
    RayOutputs outputs;
    PathContext ctx = recordContext(q, scratch, visit, outputs);
    std::vector<SourceSamples> sources(scene_.lights().size());
    PathState child = recordRays(q, scratch);
    double sourcesLight = 0;
    for (size_t i = 0; i < sources.size(); ++i) {
        lights_.arriving(scene_.lights()[i], q.at, SurfaceId{}, sourceSamples(q), child, ctx, sources[i]);
        for (const SourceSample& s : sources[i]) sourcesLight += brightness(s.flux);
    }
    SphereSamples samples(q.at.point, firstPassDivisions(q), Spectrum::defaultChannels());
    aimingFrom(child, q.at.point, dvec3(0), samples.strata(), false);
    tracePass(samples, 0, SurfaceId{}, child, ctx);
    int passes = volumePassesFor(samples, sourcesLight / (4 * std::numbers::pi), q.at.level);
    for (int p = 1; p < passes; ++p) tracePass(samples, samples.addPass(), SurfaceId{}, child, ctx);
    const double extinction = extinctionAt(q.at.point, child, ctx);
    VolumeRecord record = buildVolumeRecord(samples, sources, volumes_->kind().shape(), q.at.level,
                                            nearestSource(q.at.point), extinction);
    record.radius = float(heldRadius(record, extinction, child, ctx));
    return record;
}

double CacheClient::heldRadius(const VolumeRecord& r, double extinction, const PathState& state,
                               const PathContext& ctx) const {
    const RecordShape& shape = volumes_->kind().shape();
    const double eps = shape.accuracy, radius = r.radius;
    double sigma = extinction;
    for (int k = 0; k < 6; ++k) {
        dvec3 edge = r.point;
        edge[k / 2] += k % 2 ? -radius : radius;
        sigma = std::max(sigma, extinctionAt(edge, state, ctx));
    }
    return std::max(std::min(radius, eps / std::max(sigma, 1e-300)), std::min(radius, eps * shape.minRadius));
}

double CacheClient::extinctionAt(const dvec3& p, const PathState& state, const PathContext& ctx) const {
    HomogeneousMedium h = media_.homogeneousAlong(Ray{p, dvec3(0, 0, 1)}, nullptr, state);
    return (h.extinction + ctx.smoke.smokeExtinction(p)).maxValue();
}

int CacheClient::volumePassesFor(const SphereSamples& first, double known, int level) const {
    if (level > 0) return 1;
    double light = first.meanBrightness() + known;
    double target = kVolumeNoiseShare * settings_.ambientAccuracy;
    return light > 0 ? samplePasses(first.meanStandardError() / light, target, kVolumePasses) : 1;
}

}  // namespace brume
