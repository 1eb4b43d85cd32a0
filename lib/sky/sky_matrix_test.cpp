#include "sky/sky_matrix.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

namespace brume {
namespace {

WeatherSite chicago() {
    WeatherSite s;
    s.latitude = 41.98, s.longitude = -87.92, s.timeZone = -6;
    return s;
}

WeatherRecord record(int month, int day, double hour, double direct, double diffuse) {
    WeatherRecord r;
    r.month = month, r.day = day, r.hour = hour, r.direct = direct, r.diffuse = diffuse;
    return r;
}

// Solar units (-O1), with the sky's, the sun's and the ground's colours.
SkyMatrixOptions solar(Rgb sky, Rgb sun, Rgb ground) {
    SkyMatrixOptions o;
    o.solarRadiance = true;
    o.skyColour = sky, o.sunColour = sun, o.groundReflectance = ground;
    return o;
}

// What the patches give a horizontal plane, Σ L sin(altitude) Ω, in one channel.
double horizontal(const SkyStep& s, const SkyPatches& p, int channel, bool exactSine) {
    double e = 0;
    for (int i = 1; i < p.size(); ++i)
        e += s.patches[3 * i + channel] * (exactSine ? std::sin(double(p[i].altitude)) : tabulatedSine(p[i].altitude)) * p[i].solidAngle;
    return e;
}

// In solar units (-O1) the sky gives the record's diffuse irradiance on the ground: exactly as gendaymtx sums
// (Radiance's tabulated sine), within the patches' quadrature with the true sine; the sky's colour scales
// each channel.
TEST(SkyMatrix, SkyGivesTheDiffuseIrradiance) {
    SkyMatrixOptions o = solar({0.96, 1.004, 1.118}, {0, 0, 0}, {0.2, 0.2, 0.2});
    for (int m : {1, 2}) {
        o.subdivisions = m;
        SkySteps steps(chicago(), WeatherUnits::DirectNormalIrradiance, o);
        for (auto [month, hour, direct, diffuse] : {std::tuple{6, 12.5, 800.0, 100.0}, std::tuple{12, 9.5, 50.0, 150.0},
                                                    std::tuple{3, 16.5, 600.0, 60.0}}) {
            std::optional<SkyStep> s = steps.step(record(month, 21, hour, direct, diffuse));
            ASSERT_TRUE(s);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(horizontal(*s, steps.patches(), c, false), diffuse * o.skyColour[c], 1e-5 * diffuse);
                EXPECT_NEAR(horizontal(*s, steps.patches(), c, true), diffuse * o.skyColour[c], 0.01 * diffuse);
            }
        }
    }
}

// The sun alone (-d, -O1): its patches' radiance times their solid angle is the direct normal irradiance,
// spread over the four patches nearest the sun (or, with -5, in the nearest at the sun's own solid angle);
// the ground (-s) reflects the global irradiance.
TEST(SkyMatrix, SunAndGroundCarryTheDirectAndGlobalIrradiance) {
    SkyMatrixOptions o = solar({0, 0, 0}, {1, 1, 1}, {0, 0, 0});
    SkySteps sun(chicago(), WeatherUnits::DirectNormalIrradiance, o);
    std::optional<SkyStep> s = sun.step(record(6, 21, 12.5, 800, 100));
    ASSERT_TRUE(s);
    double total = 0, weighted = 0;
    int lit = 0;
    for (int i = 1; i < sun.patches().size(); ++i) {
        double e = s->patches[3 * i + 1] * sun.patches()[i].solidAngle;
        total += e;
        lit += e > 0;
        weighted += e * glm::dot(sun.patches().direction(i), s->sunDirection);
    }
    EXPECT_NEAR(total, 800, 1e-3);
    EXPECT_EQ(lit, 4);
    EXPECT_GT(weighted / total, std::cos(12 * kDegree));  // within a patch of the sun
    o.sunPatches = 1, o.sunSolidAngle = 6.8e-5;
    SkySteps five(chicago(), WeatherUnits::DirectNormalIrradiance, o);
    std::optional<SkyStep> f = five.step(record(6, 21, 12.5, 800, 100));
    double peak = 0;
    for (int i = 1; i < five.patches().size(); ++i) peak = std::max(peak, double(f->patches[3 * i]));
    EXPECT_NEAR(peak * 6.8e-5, 800, 1e-3);

    SkyMatrixOptions g = solar({0.96, 1.004, 1.118}, {0, 0, 0}, {0.2, 0.3, 0.4});
    SkySteps ground(chicago(), WeatherUnits::DirectNormalIrradiance, g);
    std::optional<SkyStep> t = ground.step(record(6, 21, 12.5, 800, 100));
    double altitude = std::asin(t->sunDirection.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t->patches[c], g.groundReflectance[c] * (100 + 800 * std::sin(altitude)) / kPi, 1e-4);
}

// Dark hours are black; -u skips the hours with the sun down; direct horizontal input (units 2) gives the
// sky of the direct normal irradiance it stands for; a record without irradiances is an error.
TEST(SkyMatrix, NightsSunHoursAndUnits) {
    SkyMatrixOptions o;
    SkySteps steps(chicago(), WeatherUnits::DirectNormalIrradiance, o);
    std::optional<SkyStep> night = steps.step(record(1, 1, 0.5, 0, 0));
    ASSERT_TRUE(night);
    EXPECT_TRUE(night->dark);
    for (float v : night->patches) EXPECT_EQ(v, 0.f);
    o.sunHoursOnly = true;
    SkySteps day(chicago(), WeatherUnits::DirectNormalIrradiance, o);
    EXPECT_FALSE(day.step(record(1, 1, 0.5, 0, 0)));
    std::optional<SkyStep> normal = steps.step(record(6, 21, 12.5, 800, 100));
    SkySteps horizontalInput(chicago(), WeatherUnits::DirectHorizontalIrradiance, SkyMatrixOptions{});
    std::optional<SkyStep> h = horizontalInput.step(record(6, 21, 12.5, 800 * normal->sunDirection.z, 100));
    for (size_t i = 0; i < h->patches.size(); ++i) EXPECT_NEAR(h->patches[i], normal->patches[i], 1e-4 * std::max(1.f, normal->patches[i]));
    WeatherRecord missing = record(6, 21, 12.5, 800, 100);
    missing.direct.reset();
    EXPECT_THROW(steps.step(missing), Error);
}

}  // namespace
}  // namespace brume
