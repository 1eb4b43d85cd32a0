// Contributions (lib/integrator/contributions.h): what each source's emission adds to a query's value, as
// rcontrib bins it. Over a query they sum to the value the integrator returns (every multiplication on the
// way down carried forward, every emission told once); and under an open sky a sensor's coefficient per
// Tregenza patch is ∫cosθ dω over the patch, in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "integrator/contributions.h"
#include "integrator/testing.h"
#include "scene_text.h"
#include "sky/sky_patches.h"

using namespace brume;

namespace {

constexpr double kPi = std::numbers::pi;

// Σ coefficient × radiance per modifier (first channel), and per sky patch of the ray's direction.
class Tally final : public ContributionSink {
public:
    explicit Tally(const SkyPatches* patches = nullptr) : patches_(patches) {}
    void add(const Contribution& c) override {
        EXPECT_NEAR(glm::length(c.dir), 1.0, 1e-9);
        EXPECT_TRUE(std::isfinite(c.coefficient[0]));
        double v = double(c.coefficient[0]) * c.radiance[0];
        byModifier[c.modifier] += v;
        total += v;
        if (patches_) byPatch[patches_->patchAt(c.dir)] += c.coefficient[0];
    }
    std::map<int, double> byModifier, byPatch;
    double total = 0;

private:
    const SkyPatches* patches_;
};

RenderSettings pathTracing(int bounces, int divisions) {
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = bounces;
    s.ambientAccuracy = 0;
    s.ambientDivisions = divisions;
    s.minWeight = 1e-3;
    return s;
}

enum class Query { Ray, Sensor, AtHit };

// The value of one query, and the contributions it told.
double traced(const Integrator& integrator, Query kind, const dvec3& org, const dvec3& dir, uint64_t index,
              Tally& tally) {
    Scratch scratch(integrator.scene());
    WorkItem item{scratch, nullptr, &tally};
    RayQuery q{org, dir, index, 0};
    RayRecord r = kind == Query::Ray      ? integrator.trace(q, item)
                  : kind == Query::Sensor ? integrator.irradiance(q, item)
                                          : integrator.irradianceAtHit(q, item);
    return r.value[0];
}

// Every query's contributions sum to its value: float rounding of a few hundred terms (1e-5 relative) and
// nothing more, whatever carried the light there.
void expectSumsToValue(const std::string& text, const RenderSettings& s, Query kind, const dvec3& org,
                       const dvec3& dir, int queries = 8) {
    test::TestScene scene(text);
    Integrator integrator(scene.render, s);
    double values = 0;
    for (int i = 0; i < queries; ++i) {
        Tally tally;
        double value = traced(integrator, kind, org, dir, uint64_t(i), tally);
        EXPECT_NEAR(tally.total, value, 1e-5 * std::abs(value) + 1e-9) << "query " << i;
        values += value;
    }
    EXPECT_GT(values, 0) << "nothing lit: the test would prove nothing";
}

const char* kSun = "void light sun_light 0 0 3 6e6 6e6 6e6\nsun_light source sun 0 0 4 .3 -.8 .6 .533\n";

TEST(Contributions, SensorsInADaylitRoomSumToTheirValue) {
    std::string room = integrator_testing::daylitRoom(0.5);
    expectSumsToValue(room, pathTracing(3, 64), Query::Sensor, {2, 2, 0.8}, {0, 0, 1});
    expectSumsToValue(room + kSun, pathTracing(3, 64), Query::Sensor, {2, 2, 0.8}, {0, 0, 1});
    RenderSettings noPortals = pathTracing(2, 64);
    noPortals.skyPortals = false;
    expectSumsToValue(room + kSun, noPortals, Query::Sensor, {2, 3, 0.8}, {0, -1, 0});
}

TEST(Contributions, RaysThroughGlossyMirrorAndPatternedSurfacesSumToTheirValue) {
    std::string room = integrator_testing::daylitRoom(0.5, std::string(kSun) +
        "void plastic gloss 0 0 5 .4 .4 .4 .05 .08\n"
        "gloss sphere ball 0 0 4 2 2 .5 .4\n"
        "void mirror silver 0 0 3 .9 .9 .9\n"
        "silver polygon glass_top 0 0 12 .5 3.5 .01 1.5 3.5 .01 1.5 3.9 .01 .5 3.9 .01\n"
        "void metal brushed 0 0 5 .7 .7 .7 .9 .15\n"
        "brushed sphere knob 0 0 4 3 3 .3 .3\n"
        "void trans veil 0 0 7 .6 .6 .6 0 0 .5 .2\n"
        "veil polygon curtain 0 0 12 1 .5 .2 3 .5 .2 3 .5 2.5 1 .5 2.5\n"
        "void light lamp 0 0 3 50 50 50\n"
        "lamp sphere bulb 0 0 4 3.5 3.5 2.7 .05\n");
    RenderSettings s = pathTracing(2, 32);
    for (dvec3 dir : {dvec3(0, .3, -1), dvec3(.2, .9, -.3), dvec3(-.6, -.3, -.2), dvec3(.5, .5, .1)})
        expectSumsToValue(room, s, Query::Ray, {2, 1.2, 1.5}, dir, 4);
    expectSumsToValue(room, s, Query::AtHit, {2, 1.2, 1.5}, {0, .3, -1}, 4);
}

TEST(Contributions, IllumWindowsAndMixturesSumToTheirValue) {
    std::string room = integrator_testing::daylitRoom(0.6,
        "void illum pane_light 0 0 3 3 3 3\n"
        "pane_light polygon lit 0 0 12 1 .001 1 1 .001 2 3 .001 2 3 .001 1\n"
        "void plastic red 0 0 5 .6 .1 .1 0 0\n"
        "void plastic blue 0 0 5 .1 .1 .6 0 0\n"
        "void mixfunc mix 4 red blue .5+.5*sin(8*Px) . 0 0\n"
        "mix polygon rug 0 0 12 1 1 .01 3 1 .01 3 3 .01 1 3 .01\n");
    expectSumsToValue(room, pathTracing(2, 32), Query::Ray, {2, 2, 1.5}, {0, 0, -1});
    expectSumsToValue(room, pathTracing(2, 32), Query::Sensor, {2, 2, 0.5}, {0, 0, 1});
}

// Tregenza's patch i as reinhart.cal's bin (1 to 145): its rows of 12° from the horizon up (30, 30, 24, 24, 18,
// 12, 6 patches) and the zenith cap; ∫cosθ dω over it = Δφ (sin² a₂ − sin² a₁) / 2.
double projectedSolidAngle(int patch) {
    const int counts[] = {30, 30, 24, 24, 18, 12, 6, 1};
    int first = 1;
    for (int row = 0; row < 8; ++row) {
        if (patch < first + counts[row]) {
            double a1 = row * 12 * kPi / 180, a2 = row == 7 ? kPi / 2 : (row + 1) * 12 * kPi / 180;
            return 2 * kPi / counts[row] * (std::pow(std::sin(a2), 2) - std::pow(std::sin(a1), 2)) / 2;
        }
        first += counts[row];
    }
    return 0;
}

TEST(Contributions, ASensorUnderAnOpenSkyGetsEachPatchsProjectedSolidAngle) {
    test::TestScene scene("void glow sky 0 0 4 1 1 1 0\nsky source dome 0 0 4 0 0 1 180\n");
    Integrator integrator(scene.render, pathTracing(1, 4096));
    SkyPatches tregenza(1);
    Tally tally(&tregenza);
    const int queries = 16;
    for (int i = 0; i < queries; ++i) traced(integrator, Query::Sensor, {0, 0, 0}, {0, 0, 1}, uint64_t(i), tally);
    // Each ray brings π/N where it falls in the patch: a binomial count's deviation bounds the noise (stratified
    // rays have less); 5 of them per patch.
    const double rays = 4096.0 * queries;
    double sum = 0;
    for (int patch = 1; patch <= 145; ++patch) {
        double expected = projectedSolidAngle(patch), p = expected / kPi;
        double got = tally.byPatch[patch] / queries;
        EXPECT_NEAR(got, expected, 5 * kPi * std::sqrt(p * (1 - p) / rays) + 1e-9) << "patch " << patch;
        sum += got;
    }
    EXPECT_NEAR(sum, kPi, 1e-4);
    EXPECT_EQ(tally.byPatch.count(0), 0u);  // nothing from below the horizon
}

TEST(Contributions, TheSunsCoefficientIsItsSolidAngleTimesCosine) {
    test::TestScene scene(kSun);
    Integrator integrator(scene.render, pathTracing(1, 64));
    SkyPatches tregenza(1);
    Tally tally(&tregenza);
    const int queries = 64;
    for (int i = 0; i < queries; ++i) traced(integrator, Query::Sensor, {0, 0, 0}, {0, 0, 1}, uint64_t(i), tally);
    dvec3 toSun = glm::normalize(dvec3(.3, -.8, .6));
    double halfAngle = 0.533 / 2 * kPi / 180, solidAngle = 2 * kPi * (1 - std::cos(halfAngle));
    ASSERT_EQ(tally.byPatch.size(), 1u);
    EXPECT_EQ(tally.byPatch.begin()->first, tregenza.patchAt(toSun));
    // In closed form at a sensor (the disc's cosine varies by ±0.7 % across it): within 0.1 % over 64 sensors.
    EXPECT_NEAR(tally.byPatch.begin()->second / queries, solidAngle * toSun.z, 1e-3 * solidAngle * toSun.z);
}

TEST(Contributions, AreRefusedWhereRecordsOrMediaWouldLoseThem) {
    test::TestScene scene("void glow sky 0 0 4 1 1 1 0\nsky source dome 0 0 4 0 0 1 180\n"
                          "void mist fog 0 0 3 .1 .1 .1\nfog sphere cloud 0 0 4 0 0 0 10\n");
    Integrator integrator(scene.render, pathTracing(1, 16));
    Tally tally;
    EXPECT_NE(test::errorOf([&] { traced(integrator, Query::Sensor, {0, 0, 0}, {0, 0, 1}, 0, tally); }), "no error");
}

}  // namespace
