// The volume irradiance cache (records in media) against closed forms and against path tracing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "integrator/testing.h"
#include "render/sequence.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;
using std::numbers::pi;

namespace {

RenderSettings inFog(double extinction, double albedo, double g, int bounces, double accuracy) {
    RenderSettings s = fixedSeed();
    s.medium.extinction = Spectrum(float(extinction)), s.medium.albedo = Spectrum(float(albedo)), s.medium.g = g;
    s.ambientBounces = bounces, s.ambientAccuracy = accuracy;
    return s;
}

}  // namespace

// Energy: a grey sphere (ρ = 0.8) filled with a white fog (σ = 1 per radius, albedo 1) loses light only at
// its walls, so the mean wall irradiance is Φ/(4πR²(1 − ρ)), fog or not, for an isotropic and a forward
// (g 0.6) lobe: the caches at their defaults (-ab 8 here, past it by roulette; sensors on the walls, whose
// records' rays cross the fog, and few enough that deeper volume records seldom pay for themselves there).
// 64 sensors of about 3% noise each (measured): the mean within 2%, four standard errors of it and the bias
// interpolation and the records' clamped harmonics may add (measured -0.8% and -0.5%).
TEST(VolumeCache, AWhiteFogInAClosedSphereKeepsItsEnergy) {
    const double expected = 4 * pi * 0.02 * 0.02 * pi * 1000 / (4 * pi) / (1 - 0.8);
    TestScene t(integratingSphere(0.8));
    for (double g : {0.0, 0.6}) {
        Sequence sequence(t.scene, t.render, inFog(1, 1, g, 8, 0.1));
        ASSERT_NE(sequence.volumes(), nullptr);
        const int n = 64;
        std::vector<double> values(n);
        sequence.run(n, 0, [&](size_t i, WorkItem& item) {
            dvec3 d = fibonacciSphere(i, n);
            values[i] = sequence.integrator().irradiance({d * (1 - 1e-4), -d, i}, item).value[0];
        });
        double mean = 0;
        for (double v : values) mean += v / n;
        EXPECT_NEAR(mean, expected, 0.02 * expected) << "g " << g;
    }
}

// Run to run, sensors in a white fog: in the grey sphere (ρ 0.5) of albedo-1 fog, a sensor's record sees the
// light of many-bounce paths through the fog along its rays, so that its 1024 rays make a record some 3 %
// noisy; such records take more passes (CacheClient::passesFor: four or more). Two runs of 24 wall sensors
// with different seeds, at the defaults (-ab 8): their relative differences' RMS / √2 is a run's spread,
// 2.65 % with one pass per record, 1.25 % with the passes (measured). The estimate's own relative error is
// about 1/√48 ≈ 14 %: below 1.9 %, three of those above what the passes give and two below what one pass
// gives.
TEST(VolumeCache, SensorsInAWhiteFogAreAsSteadyAsTheirRecordsAim) {
    TestScene t(integratingSphere(0.5));
    const int n = 24;
    std::vector<double> runs[2];
    for (uint64_t seed : {1, 2}) {
        RenderSettings s = inFog(1, 1, 0, 8, 0.1);
        s.seed = seed;
        Sequence sequence(t.scene, t.render, s);
        std::vector<double>& values = runs[seed - 1];
        values.resize(n);
        sequence.run(n, 0, [&](size_t i, WorkItem& item) {
            dvec3 d = fibonacciSphere(i, n);
            values[i] = sequence.integrator().irradiance({d * (1 - 1e-4), -d, i}, item).value[0];
        });
    }
    double squares = 0;
    for (int i = 0; i < n; ++i) {
        double d = (runs[0][i] - runs[1][i]) / (runs[0][i] + runs[1][i]) * 2;
        squares += d * d / n;
    }
    EXPECT_LT(std::sqrt(squares / 2), 0.019);
}

namespace {

const std::string kFoggyRoom = "void plastic grey 0 0 5 .6 .6 .6 0 0\n"
                               "grey polygon floor 0 0 12 0 0 0 0 4 0 4 4 0 4 0 0\n"
                               "grey polygon ceiling 0 0 12 0 0 3 4 0 3 4 4 3 0 4 3\n"
                               "grey polygon west 0 0 12 0 0 0 0 0 3 0 4 3 0 4 0\n"
                               "grey polygon east 0 0 12 4 0 0 4 4 0 4 4 3 4 0 3\n"
                               "grey polygon south 0 0 12 0 0 0 4 0 0 4 0 3 0 0 3\n"
                               "grey polygon north 0 0 12 0 4 0 0 4 3 4 4 3 4 4 0\n"
                               "void light lamp 0 0 3 2 2 2\n"
                               "lamp sphere bulb 0 0 4 1 2 2.2 0.25\n";

struct Fog {
    double extinction, albedo, g;
    int bounces;
};

struct EyeRay {
    dvec3 eye, dir;
};

// The mean radiance of view rays [checked, rays.size()) in `text`'s scene: path traced (`passes` passes: the
// reference and its standard error), and from the caches (-aa .1, -al+: no bounces past -ab, as path tracing)
// after the rays before them made their records.
struct Compared {
    integrator_testing::Mean reference;
    double cached = 0;
};

Compared compareViewRays(const std::string& text, const std::vector<EyeRay>& rays, size_t checked, const Fog& c,
                         int passes = 64) {
    TestScene t(text);
    Integrator paths(t.render, inFog(c.extinction, c.albedo, c.g, c.bounces, 0));
    const double n = double(rays.size() - checked);
    Compared out;
    for (int k = 0; k < passes; ++k) {
        double pass = 0;
        for (size_t i = checked; i < rays.size(); ++i) pass += trace(paths, rays[i].eye, rays[i].dir, i * 1000 + k).value[0] / n;
        out.reference.add(pass);
    }
    RenderSettings cache = inFog(c.extinction, c.albedo, c.g, c.bounces, 0.1);
    cache.ambientLimit = true;
    Sequence sequence(t.scene, t.render, cache);
    std::vector<double> cached(rays.size());
    for (auto [first, last] : {std::pair{size_t(0), checked}, std::pair{checked, rays.size()}})
        sequence.run(last - first, 0, [&](size_t k, WorkItem& item) {
            size_t i = first + k;
            cached[i] = sequence.integrator().trace({rays[i].eye, rays[i].dir, i}, item).value[0];
        });
    for (size_t i = checked; i < rays.size(); ++i) out.cached += cached[i] / n;
    EXPECT_GT(sequence.volumes()->size(), 0u);
    return out;
}

}  // namespace

// View rays through a lit fog in a closed room, cached against path traced: the mean radiance of 24 view
// rays across the room (the fog's light, the lamp's scattered once among it, and the walls behind it), for a
// forward and a backward lobe at -ab 1 and 2, within 5 % plus three standard errors of the reference (whose
// own is 2-3 %: a view ray's one in-scattering sample varies much; the cache's run-to-run spread over these
// rays is about 4 %).
TEST(VolumeCache, ViewRaysThroughFogAgreeWithPathTracing) {
    std::vector<EyeRay> rays;
    for (size_t i = 0; i < 24; ++i)
        rays.push_back({dvec3(3.5, 0.5, 1.2),
                        glm::normalize(dvec3(-1, 0.2 + 0.05 * double(i % 12), -0.3 + 0.15 * double(i / 12)))});
    for (Fog c : {Fog{0.5, 0.9, 0.6, 1}, Fog{0.3, 0.8, -0.3, 2}}) {
        SCOPED_TRACE(testing::Message() << "σ " << c.extinction << " albedo " << c.albedo << " g " << c.g << " -ab "
                                        << c.bounces);
        Compared r = compareViewRays(kFoggyRoom, rays, 0, c);
        EXPECT_NEAR(r.cached, r.reference.value(), 0.05 * r.reference.value() + 3 * r.reference.standardError());
    }
}

// Records hold the lamp's light arriving at their points, and a zone never reaches past the nearest surface
// its rays met: a black partition hanging from the ceiling to 0.8 m at x = 2 hides the lamp from view rays
// along it 0.1 m behind it, which see only what the floor and the fog sent on, 0.15 % of what the same rays see
// 0.1 m before it (path traced; their far wall black, so that the surface cache plays no part). The rays
// before it make their records first; those behind it must not take them (with zones sized by the lamp's
// distance alone they saw 450 times their light). Within 5 % plus three standard errors of a reference of
// 256 passes (its own about 20 %).
TEST(VolumeCache, ALampsLightInRecordsStaysOutOfItsShadow) {
    const std::string partitioned = "void plastic black 0 0 5 0 0 0 0 0\n" + kFoggyRoom +
                                    "black polygon partition 0 0 12 2 0 0.8 2 4 0.8 2 4 3 2 0 3\n"
                                    "black polygon far_wall 0 0 12 0 3.999 0 0 3.999 3 4 3.999 3 4 3.999 0\n";
    std::vector<EyeRay> rays;
    for (double x : {1.9, 2.1})
        for (size_t i = 0; i < 12; ++i)
            rays.push_back({dvec3(x, 0.1, 1.9), glm::normalize(dvec3(0, 1, 0.05 * (double(i) - 5.5)))});
    Compared r = compareViewRays(partitioned, rays, 12, Fog{0.5, 0.9, 0.6, 1}, 256);
    EXPECT_NEAR(r.cached, r.reference.value(), 0.05 * r.reference.value() + 3 * r.reference.standardError());
}
