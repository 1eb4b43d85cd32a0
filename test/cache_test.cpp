// The irradiance cache against closed-form answers and against a converged path-traced reference.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <tbb/global_control.h>

#include "scene/reader.h"
#include "integrator/testing.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;
using std::numbers::pi;

namespace {

struct Sensor {
    dvec3 point, normal;
};

// Irradiance (luminance channel weights) at each sensor, as rtrace -I computes it: through the cache's passes.
std::vector<double> sensorValues(Sequence& sequence, const std::vector<Sensor>& sensors) {
    std::vector<double> values(sensors.size());
    sequence.run(sensors.size(), 0, [&](size_t i, WorkItem& item) {
        values[i] = brightness(sequence.integrator().irradiance({sensors[i].point, sensors[i].normal, i}, item).value);
    });
    return values;
}

RenderSettings cached(int bounces, double accuracy = 0.1) {
    RenderSettings s = fixedSeed();
    s.ambientBounces = bounces;
    s.ambientAccuracy = accuracy;
    return s;
}

std::vector<Sensor> onTheSphere(int n) {
    std::vector<Sensor> sensors;
    for (int i = 0; i < n; ++i) {  // over the wall, facing the centre
        dvec3 d = fibonacciSphere(i, n);
        sensors.push_back({d * (1 - 1e-4), -d});
    }
    return sensors;
}

}  // namespace

// ρ = 0.8 needs all bounces (1/(1 − ρ) = 5 times the direct light): Radiance's cache at -ab 20 takes
// minutes there; the cache's records plus Russian roulette past -ab reach it at -ab 5 and at -ab 20.
// Tolerances: the mean within 1% (64 sensors, each ~1% noise: 1024 samples per record, deeper bounces
// by fewer-sampled records and roulette); each sensor within 3.5%, under half of -aa .1 of the indirect
// light (80% of the whole at ρ = 0.8).
TEST(CachedIrradiance, IntegratingSphereReachesTheAllBounceAnswer) {
    const double direct = 4 * pi * 0.02 * 0.02 * pi * 1000 / (4 * pi);
    for (double rho : {0.5, 0.8}) {
        TestScene t(integratingSphere(rho));
        for (int bounces : {5, 20}) {
            if (rho < 0.8 && bounces > 5) continue;  // nothing left to show there
            Sequence sequence(t.scene, t.render, cached(bounces));
            std::vector<double> values = sensorValues(sequence, onTheSphere(64));
            double expected = direct / (1 - rho), mean = 0;
            for (size_t i = 0; i < values.size(); ++i) {
                ASSERT_NEAR(values[i], expected, 0.035 * expected) << "rho " << rho << " -ab " << bounces << " #" << i;
                mean += values[i] / values.size();
            }
            EXPECT_NEAR(mean, expected, 0.01 * expected) << "rho " << rho << " -ab " << bounces;
        }
    }
}

// An open scene whose light is all indirect: a wide ground of reflectance ρ under a uniform sky of
// radiance L. The ground's radiance is ρL, so a sensor facing down receives πρL, one facing sideways
// πL/2 from the sky and πρL/2 from the ground. Tolerance 2% (the ground's edge is 500 m away: it hides
// less than 1e-5 of the view; 1024 samples per record).
TEST(CachedIrradiance, GroundUnderAUniformSkyGivesPiRhoL) {
    TestScene t("void glow skyglow 0 0 4 2 2 2 0\n"
                "skyglow source sky 0 0 4 0 0 1 180\n"
                "void plastic ground 0 0 5 .3 .3 .3 0 0\n"
                "ground polygon floor 0 0 12 -500 -500 0 500 -500 0 500 500 0 -500 500 0\n");
    Sequence sequence(t.scene, t.render, cached(2));
    std::vector<Sensor> sensors;
    for (int i = 0; i < 16; ++i) sensors.push_back({dvec3(0.37 * i - 3, 0.21 * i, 1 + 0.1 * i), dvec3(0, 0, -1)});
    for (int i = 0; i < 8; ++i) sensors.push_back({dvec3(0.5 * i, -1, 1.5), dvec3(std::cos(i), std::sin(i), 0)});
    std::vector<double> values = sensorValues(sequence, sensors);
    for (size_t i = 0; i < values.size(); ++i) {
        double expected = i < 16 ? pi * 0.3 * 2 : pi * 2 / 2 + pi * 0.3 * 2 / 2;
        EXPECT_NEAR(values[i], expected, 0.02 * expected) << "sensor " << i;
    }
}

// The same records whatever the number of threads: the passes fix their order.
TEST(CachedIrradiance, RecordsDoNotDependOnTheThreadCount) {
    TestScene t(integratingSphere(0.5) + "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                                         "grey polygon shelf 0 0 12 -.5 -.5 -.2 .5 -.5 -.2 .5 .5 -.2 -.5 .5 -.2\n");
    auto run = [&](int threads) {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
        Sequence sequence(t.scene, t.render, cached(3, 0.2));
        return sensorValues(sequence, onTheSphere(100));
    };
    EXPECT_EQ(run(1), run(2));
}

// So do records that aim at the sky through windows and at a sun patch (their aimed samples draw from each
// record's own stream).
TEST(CachedIrradiance, DaylitRecordsDoNotDependOnTheThreadCount) {
    TestScene t(integrator_testing::daylitRoom(
        0.6, "void light solar 0 0 3 2e5 2e5 2e5\nsolar source sun 0 0 4 .6 -1 .8 0.5\n"));
    std::vector<Sensor> sensors;
    for (int i = 0; i < 25; ++i) sensors.push_back({dvec3(0.4 + 0.8 * (i % 5), 0.4 + 0.8 * (i / 5), 0.8), dvec3(0, 0, 1)});
    auto run = [&](int threads) {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
        Sequence sequence(t.scene, t.render, cached(3, 0.2));
        return sensorValues(sequence, sensors);
    };
    EXPECT_EQ(run(1), run(2));
}

// The splotch test: on the example office (424 sensors: a work-plane grid reaching 12.5 cm from the walls
// and sensors on the walls), the cache's error against a converged path-traced reference
// (test/data/cache/office_sensors_reference.txt, its indirect part known to ~0.3%) stays within -aa of
// the indirect light at 99% of the sensors, and within three times that everywhere. (At -aa .05 the
// records' own noise at the default -ad 1024, ~2.3% of the indirect light, needs -ad 4096 to pass.) The same
// holds with the office at its site's UTM coordinates.
TEST(CachedIrradiance, OfficeSensorsStayWithinTheAccuracyOfTheIndirectLight) {
    const std::string data = std::string(BRUME_TEST_DATA) + "/cache/office_sensors_reference.txt";
    std::vector<Sensor> sensors;
    std::vector<double> total, direct;
    std::ifstream in(data);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        Sensor s;
        double t, d;
        f >> s.point.x >> s.point.y >> s.point.z >> s.normal.x >> s.normal.y >> s.normal.z >> t >> d;
        sensors.push_back(s), total.push_back(t), direct.push_back(d);
    }
    ASSERT_EQ(sensors.size(), 424u);
    const std::string office = std::string(BRUME_TEST_DATA) + "/../../examples/office/office.rad";
    // At the origin, and at its site's UTM coordinates (the same scene and sensors, moved).
    for (dvec3 offset : {dvec3(0), dvec3(512345.6, 5412345.7, 120)}) {
        char xform[128];
        std::snprintf(xform, sizeof xform, "!xform -t %.17g %.17g %.17g ", offset.x, offset.y, offset.z);
        TestScene t(xform + office + "\n");
        std::vector<Sensor> moved = sensors;
        for (Sensor& s : moved) s.point += offset;
        Sequence sequence(t.scene, t.render, cached(5, 0.1));
        std::vector<double> values = sensorValues(sequence, moved);
        int within = 0;
        double worst = 0, squares = 0;
        for (size_t i = 0; i < sensors.size(); ++i) {
            double error = std::abs(values[i] - total[i]) / (total[i] - direct[i]);
            within += error <= 0.1;
            worst = std::max(worst, error);
            squares += error * error;
        }
        std::printf("offset %g %g %g: %d of %zu sensors within -aa of the indirect light, RMS %.2f%%, worst %.2f%%; %s\n",
                    offset.x, offset.y, offset.z, within, sensors.size(), 100 * std::sqrt(squares / sensors.size()),
                    100 * worst, sequence.cache()->summary().c_str());
        EXPECT_GE(within, int(0.99 * sensors.size())) << "offset " << offset.x;
        EXPECT_LE(worst, 3 * 0.1) << "offset " << offset.x;
    }
}

// Records hold diffuse irradiance only: the glossy reflection of a shiny floor is sampled by rays at every
// look, so a glossy room seen through the cache equals its path-traced picture. Tolerance 3% on the mean
// of 64 view rays (the path-traced side has ~1% noise; the cache's records ~2% each).
TEST(CachedIrradiance, GlossySurfacesKeepTheirHighlights) {
    TestScene t("void light lum 0 0 3 50 50 50\n"
                "lum polygon panel 0 0 12 -.5 -.5 2.9 .5 -.5 2.9 .5 .5 2.9 -.5 .5 2.9\n"
                "void plastic shiny 0 0 5 .4 .4 .4 .08 .05\n"
                "void plastic paint 0 0 5 .6 .6 .6 0 0\n"
                "shiny polygon floor 0 0 12 -3 -3 0 3 -3 0 3 3 0 -3 3 0\n"
                "paint polygon ceiling 0 0 12 -3 -3 3 -3 3 3 3 3 3 3 -3 3\n"
                "paint polygon north 0 0 12 -3 3 0 3 3 0 3 3 3 -3 3 3\n"
                "paint polygon south 0 0 12 -3 -3 0 -3 -3 3 3 -3 3 3 -3 0\n"
                "paint polygon east 0 0 12 3 -3 0 3 3 0 3 3 3 3 -3 3\n"
                "paint polygon west 0 0 12 -3 -3 0 -3 -3 3 -3 3 3 -3 3 0\n");
    auto meanOfRays = [&](const RenderSettings& s) {
        Sequence sequence(t.scene, t.render, s);
        std::vector<double> values(64);
        sequence.run(values.size(), 0, [&](size_t i, WorkItem& item) {
            dvec3 target(-1.5 + 0.4 * (i % 8), -1.5 + 0.4 * double(i / 8), 0);  // floor points, some in the highlight
            dvec3 eye(-2.5, -2.5, 1.5);
            values[i] = brightness(sequence.integrator().trace({eye, target - eye, i}, item).value);
        });
        double sum = 0;
        for (double v : values) sum += v;
        return sum / values.size();
    };
    RenderSettings pathTraced = cached(50, 0);
    pathTraced.ambientDivisions = 2048;
    double expected = meanOfRays(pathTraced);
    EXPECT_NEAR(meanOfRays(cached(2)), expected, 0.03 * expected);
}

// Records take the sky through the windows and the sun's patches by their aimed samples too (SkyPortals,
// SunPatches): a side-lit room with a sun patch, 16 sensors at the cache's defaults against path tracing
// (each sensor the mean of 32 runs of 256 paths, ~0.4% noise). Tolerances: the mean within 1.5% (16
// records' noise of ~1% each, averaged), each sensor within 6% (interpolation beside the patch's edge).
TEST(CachedIrradiance, DaylitRoomSensorsAgreeWithPathTracing) {
    const std::string room = integrator_testing::daylitRoom(
        0.6, "void light solar 0 0 3 2e5 2e5 2e5\nsolar source sun 0 0 4 .6 -1 .8 0.5\n");
    std::vector<Sensor> sensors;
    for (int i = 0; i < 16; ++i) sensors.push_back({dvec3(0.3 + (i % 4), 0.4 + 0.9 * (i / 4), 0.8), dvec3(0, 0, 1)});
    TestScene t(room);
    Sequence sequence(t.scene, t.render, cached(5, 0.1));
    std::vector<double> values = sensorValues(sequence, sensors);
    RenderSettings paths = integrator_testing::daylitPathTracing(50, 256, true);
    paths.minWeight = 1e-5;
    double sum = 0, sumReference = 0, worst = 0;
    for (size_t i = 0; i < sensors.size(); ++i) {
        double reference = integrator_testing::irradianceRuns(room, paths, sensors[i].point, sensors[i].normal, 32).mean;
        worst = std::max(worst, std::abs(values[i] / reference - 1));
        sum += values[i], sumReference += reference;
    }
    EXPECT_NEAR(sum / sumReference, 1, 0.015);
    EXPECT_LE(worst, 0.06);
}
