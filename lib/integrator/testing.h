// For the integrator's unit tests: a Tracer that answers every ray with one radiance (a uniform surrounding),
// the parts of an Integrator wired around it as Integrator's constructor wires them, and the arithmetic the
// tests' tolerances need (means with their standard errors, quadrature over directions); a daylit room.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "integrator/integrator.h"
#include "sampling/warp.h"
#include "scene_text.h"

namespace brume::integrator_testing {

// A ray a part asked the tracer about, with the state it gave it.
struct AskedRay {
    Ray ray;
    PathState state;
};

// Every ray brings `value`: the radiance of a uniform surrounding, of surfaces 1 away (a record's zone needs
// distances). Rays that may meet sources (those given a sourceShare) also bring `share` there, as a source's
// multiple-importance share would; `byRay`, where set, answers radiance() in place of `value`. The rays asked
// about are kept, by kind of question.
class ConstantTracer final : public Tracer {
public:
    explicit ConstantTracer(const Spectrum& value) : value(value) {}

    Spectrum radiance(const Ray& ray, const PathState& state, PathContext&, Spectrum* sourceShare,
                      RayRecord* record) const override {
        rays.push_back({ray, state});
        if (record) record->firstLength = record->effectiveLength = 1;
        if (sourceShare) *sourceShare += share;
        return byRay ? byRay(ray) : value;
    }
    Spectrum surfaceRadiance(const Ray& ray, const std::optional<SurfaceHit>&, const PathState& state, PathContext&,
                             Spectrum*) const override {
        surfaceRays.push_back({ray, state});
        return value;
    }
    Spectrum sampledRadiance(const dvec3& from, const SurfaceId& surface, const dvec3& dir, double, const PathState&,
                             PathState& child, PathContext&) const override {
        sampledRays.push_back({Ray{from, dir, std::numeric_limits<double>::infinity(), surface}, child});
        return value;
    }

    Spectrum value;
    Spectrum share{0.f};
    std::function<Spectrum(const Ray&)> byRay;
    mutable std::vector<AskedRay> rays, surfaceRays, sampledRays;
};

// The parts of an Integrator for the scene `text`, around a ConstantTracer of radiance 1, as Integrator's
// constructor wires them, and a scratch for the contexts of their paths.
struct Parts {
    explicit Parts(const std::string& text, const RenderSettings& s = test::fixedSeed(),
                   const SurfaceCache* surfaceCache = nullptr, const VolumeCache* volumeCache = nullptr)
        : scene(text),
          settings(inBands(s)),
          tracer(Spectrum(1.f)),
          roulette(s.maxReflections, s.minWeight),
          instants(scene.render, s.majorantCell),
          media(scene.render, settings, instants),
          shading(scene.render),
          shadowRays(scene.render, shading, media),
          lights(scene.render, settings, shading, media, shadowRays),
          portals(scene.render, shading, shadowRays, settings.skyPortals),
          patches(scene.render, shading, shadowRays, lights, settings.skyPortals),
          cache(surfaceCache, volumeCache, scene.render, settings, tracer, shading, media, lights, portals, patches,
                Seeds{s.seed}, instants.recordWindows(s.recordLifetime)),
          surfaces(scene.render, settings, lights, portals, patches, cache, tracer, roulette),
          transport(scene.render, settings, lights, cache, tracer, roulette),
          scratch(scene.render) {}

    double instant() const { return settings.time.value_or(0); }
    // The context of a work item seeded by `seed`, at the settings' instant.
    PathContext context(uint64_t seed, CacheVisit* visit = nullptr) {
        return PathContext{Random(seed, seed), scratch, instant(), media.smokeAt(instant()), visit};
    }
    // The scene object named `name` (a material's index, as hits and states name them).
    int object(const std::string& name) const {
        const auto& objects = scene.scene.objects;
        for (size_t i = 0; i < objects.size(); ++i)
            if (objects[i].name == name) return int(i);
        ADD_FAILURE() << "no object " << name;
        return -1;
    }
    // The first surface a ray from `org` toward `dir` meets.
    SurfaceHit hit(const dvec3& org, const dvec3& dir) const {
        auto h = scene.render.geometry().intersect(Ray{org, glm::normalize(dir)});
        EXPECT_TRUE(h) << "nothing seen";
        return h.value_or(SurfaceHit{});
    }

    test::TestScene scene;
    RenderSettings settings;
    ConstantTracer tracer;
    RussianRoulette roulette;
    Instants instants;
    Media media;
    HitShading shading;
    ShadowRays shadowRays;
    LightSampler lights;
    SkyPortals portals;
    SunPatches patches;
    CacheClient cache;
    SurfaceScattering surfaces;
    MediaTransport transport;
    Scratch scratch;
};

// A hit at `point` on a flat surface of normal `normal`, by a ray travelling along unit `dir` (against it).
inline Shading flatHit(const dvec3& point, const dvec3& normal, const dvec3& dir) {
    return Shading{point, normal, dir, -glm::dot(dir, normal), false, true, 1.0};
}

// The mean of draws and its standard error, for tolerances of so many standard errors.
class Mean {
public:
    void add(double x) {
        ++n_;
        sum_ += x;
        squares_ += x * x;
    }
    double value() const { return sum_ / n_; }
    double standardError() const { return std::sqrt(std::max(0.0, squares_ / n_ - value() * value()) / n_); }

private:
    long n_ = 0;
    double sum_ = 0, squares_ = 0;
};

// ∫ f(ω) dω over the hemisphere about unit `axis` (or, with `wholeSphere`, every direction), by the midpoint
// rule in θ and φ: n × 2n cells, an error of order 1/n² for smooth integrands.
inline double overDirections(const std::function<double(const dvec3&)>& f, const dvec3& axis, int n,
                             bool wholeSphere = false) {
    const double pi = std::numbers::pi, thetaMax = wholeSphere ? pi : pi / 2;
    const double dTheta = thetaMax / n, dPhi = pi / n;
    Frame frame(axis);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        double theta = (i + 0.5) * dTheta, s = std::sin(theta), c = std::cos(theta);
        for (int j = 0; j < 2 * n; ++j) {
            double phi = (j + 0.5) * dPhi;
            sum += f(frame.toWorld(dvec3(s * std::cos(phi), s * std::sin(phi), c))) * s;
        }
    }
    return sum * dTheta * dPhi;
}

// Daylit rooms. A 4 × 4 × 3 m room (x, y, z; every surface facing in) with a 2 × 1 m pane in its south wall (y = 0) and a
// triangular one in its east wall (x = 4), under a uniform sky and a darker ground; `rho` is the walls'.
inline std::string daylitRoom(double rho, const std::string& extra = "") {
    char walls[128];
    std::snprintf(walls, sizeof walls, "void plastic wall 0 0 5 %g %g %g 0 0\n", rho, rho, rho);
    return std::string("void glow sky 0 0 4 2 2 2 0\nsky source dome 0 0 4 0 0 1 180\n"
                       "void glow ground 0 0 4 .5 .5 .5 0\nground source below 0 0 4 0 0 -1 180\n"
                       "void glass pane 0 0 3 .9 .9 .9\n") +
           walls +
           "wall polygon floor 0 0 12 0 0 0 4 0 0 4 4 0 0 4 0\n"
           "wall polygon ceiling 0 0 12 0 0 3 0 4 3 4 4 3 4 0 3\n"
           "wall polygon north 0 0 12 0 4 0 4 4 0 4 4 3 0 4 3\n"
           "wall polygon west 0 0 12 0 0 0 0 4 0 0 4 3 0 0 3\n"
           "wall polygon east_below 0 0 12 4 0 0 4 0 1 4 4 1 4 4 0\n"
           "wall polygon east_above 0 0 12 4 0 2 4 0 3 4 4 3 4 4 2\n"
           "wall polygon east_south 0 0 12 4 0 1 4 0 2 4 1 2 4 1 1\n"
           "wall polygon east_north 0 0 12 4 3 1 4 3 2 4 4 2 4 4 1\n"
           "wall polygon east_left 0 0 9 4 1 1 4 1 2 4 2 2\n"
           "wall polygon east_right 0 0 9 4 2 2 4 3 2 4 3 1\n"
           "wall polygon south_below 0 0 12 0 0 0 0 0 1 4 0 1 4 0 0\n"
           "wall polygon south_above 0 0 12 0 0 2 0 0 3 4 0 3 4 0 2\n"
           "wall polygon south_west 0 0 12 0 0 1 0 0 2 1 0 2 1 0 1\n"
           "wall polygon south_east 0 0 12 3 0 1 3 0 2 4 0 2 4 0 1\n"
           "pane polygon window 0 0 12 1 0 1 1 0 2 3 0 2 3 0 1\n"
           "pane polygon east_window 0 0 9 4 3 1 4 2 2 4 1 1\n" +
           extra;
}

inline RenderSettings daylitPathTracing(int bounces, int divisions, bool portals) {
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = bounces;
    s.ambientAccuracy = 0;
    s.ambientDivisions = divisions;
    s.skyPortals = portals;
    return s;
}

struct Spread {
    double mean, standardError, deviation;
};

// `runs` independent irradiance estimates at p facing n.
inline Spread irradianceRuns(const std::string& text, const RenderSettings& s, const dvec3& p, const dvec3& n, int runs) {
    test::TestScene scene(text);
    Integrator integrator(scene.render, s);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < runs; ++i) {
        double e = test::irradiance(integrator, p, n, uint64_t(i)).value[0];
        sum += e;
        sum2 += e * e;
    }
    double mean = sum / runs, variance = std::max(0.0, sum2 / runs - mean * mean) * runs / (runs - 1);
    return {mean, std::sqrt(variance / runs), std::sqrt(variance)};
}

}  // namespace brume::integrator_testing
