#include "sky/cie_sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "sky/hemisphere_quadrature_test.h"

using namespace brume;

namespace {

// The sky's radiance toward d, as skybright.cal gives it above the horizon.
double skyRadiance(const CieSky& sky, const glm::dvec3& d) {
    return sky.zenithRadiance * cieRelativeLuminance(sky.type, sky.sunDirection, d) / sky.zenithNormalisation;
}

SunAngles sunAt(double altitudeDegrees) { return {altitudeDegrees * kDegree, 20 * kDegree}; }

// CIE S 011/E:2003 (CIE 110-1994 for the clear sky): L/Lz = f(χ) φ(Z) / (f(Zs) φ(0)), gradation
// φ(Z) = 1 + a exp(b / cos Z), indicatrix f(χ) = 1 + c (exp(d χ) - exp(d π/2)) + e cos² χ.
double cieStandardRelative(double a, double b, double c, double d, double e, const glm::dvec3& sun, const glm::dvec3& dir) {
    auto gradation = [&](double cosZ) { return 1 + a * std::exp(b / cosZ); };
    auto indicatrix = [&](double chi) { return 1 + c * (std::exp(d * chi) - std::exp(d * kPi / 2)) + e * std::pow(std::cos(chi), 2); };
    double chi = std::acos(std::clamp(glm::dot(sun, dir), -1.0, 1.0)), sunZenith = std::acos(sun.z);
    return indicatrix(chi) * gradation(dir.z) / (indicatrix(sunZenith) * gradation(1));
}

std::vector<glm::dvec3> someDirections() {
    std::vector<glm::dvec3> dirs;
    for (double alt : {2.0, 10.0, 30.0, 60.0, 89.0})
        for (double az = 0; az < 360; az += 40)
            dirs.emplace_back(std::cos(alt * kDegree) * std::sin(az * kDegree), std::cos(alt * kDegree) * std::cos(az * kDegree),
                              std::sin(alt * kDegree));
    return dirs;
}

}  // namespace

// The clear sky is the CIE standard clear sky (type 12: a=-1, b=-0.32, c=10, d=-3, e=0.45) relative to
// its zenith, to the rounding of its constants (0.91 for 0.9102, 0.274 for 1-exp(-0.32)).
TEST(CieSky, ClearSkyIsTheCieStandardClearSkyScaledToItsZenith) {
    for (double altitude : {10.0, 35.0, 60.0, 80.0}) {
        CieSky sky = makeCieSky({}, sunAt(altitude));
        glm::dvec3 zenith(0, 0, 1);
        EXPECT_NEAR(skyRadiance(sky, zenith) / sky.zenithRadiance, 1, 1e-3) << altitude;
        for (const glm::dvec3& d : someDirections())
            EXPECT_NEAR(skyRadiance(sky, d) / sky.zenithRadiance,
                        cieStandardRelative(-1, -0.32, 10, -3, 0.45, sky.sunDirection, d), 2e-3 * skyRadiance(sky, d) / sky.zenithRadiance)
                << altitude;
    }
}

// Moon & Spencer (1942), the CIE overcast sky: L = Lz (1 + 2 sin h) / 3, whatever the sun does.
TEST(CieSky, OvercastSkyIsThreeTimesBrighterAtTheZenithThanAtTheHorizon) {
    CieSkyRequest overcast;
    overcast.type = CieSkyType::Overcast;
    CieSky sky = makeCieSky(overcast, sunAt(40));
    for (const glm::dvec3& d : someDirections())
        EXPECT_NEAR(skyRadiance(sky, d), sky.zenithRadiance * (1 + 2 * d.z) / 3, 1e-12);
    EXPECT_FALSE(sky.sun);
}

// gensky's "ground ambient level" is the sky's horizontal irradiance over π: integrating the
// distribution it writes over the hemisphere gives it back, to the accuracy of gensky's polynomial fit
// of that integral (clear sky 0.3% from 5° to 87°; intermediate 2.1% up to 80°, 8.6% at 87°; the
// overcast and uniform integrals are exact).
TEST(CieSky, DistributionIntegratesToTheHorizontalIrradianceGenskyReports) {
    struct Case {
        CieSkyType type;
        double tolerance;
    };
    for (Case c : {Case{CieSkyType::Clear, 0.004}, Case{CieSkyType::Intermediate, 0.025}, Case{CieSkyType::Overcast, 1e-5},
                   Case{CieSkyType::Uniform, 1e-5}}) {
        for (double altitude : {10.0, 25.0, 45.0, 65.0, 80.0}) {
            CieSkyRequest r;
            r.type = c.type;
            CieSky sky = makeCieSky(r, sunAt(altitude));
            double integral = horizontalIntegral([&](const glm::dvec3& d) { return skyRadiance(sky, d); });
            EXPECT_NEAR(integral / (kPi * sky.ambientLevel), 1, c.tolerance) << int(c.type) << " at " << altitude << "°";
        }
    }
}

// -B gives the horizontal diffuse irradiance: the zenith radiance is scaled to it exactly.
TEST(CieSky, GivenHorizontalIrradianceSetsTheAmbientLevel) {
    for (CieSkyType type : {CieSkyType::Clear, CieSkyType::Intermediate, CieSkyType::Overcast}) {
        CieSkyRequest r;
        r.type = type;
        r.zenith = {GivenValue::Unit::Irradiance, 120};
        EXPECT_NEAR(makeCieSky(r, sunAt(30)).ambientLevel * kPi, 120, 1e-9);
    }
}

// Zenith luminance fits (Krochmann & Seidl): clear (1.376 T - 1.81) tan h + 0.38 kcd/m², overcast
// 8.6 sin h + 0.123 kcd/m², in W/sr/m² through Radiance's sky efficacy of 203 lm/W.
TEST(CieSky, ZenithLuminanceFollowsTurbidityAndSunAltitude) {
    double h = 44 * kDegree;
    EXPECT_NEAR(makeCieSky({}, {h, 0}).zenithRadiance, ((1.376 * 2.45 - 1.81) * std::tan(h) + 0.38) * 1000 / 203, 1e-9);
    CieSkyRequest turbid;
    turbid.turbidity = 5;
    EXPECT_GT(makeCieSky(turbid, {h, 0}).zenithRadiance, makeCieSky({}, {h, 0}).zenithRadiance);
    CieSkyRequest overcast;
    overcast.type = CieSkyType::Overcast;
    EXPECT_NEAR(makeCieSky(overcast, {h, 0}).zenithRadiance, (8.6 * std::sin(h) + 0.123) * 1000 / 203, 1e-9);
}

// -R gives the horizontal direct irradiance; the sun, gensky's 5.98e-5 sr disc, delivers it. The sun's
// light reaches the ground with -s as with +s.
TEST(CieSky, GivenDirectIrradianceIsWhatTheSunDelivers) {
    CieSkyRequest r;
    r.solar = {GivenValue::Unit::Irradiance, 500};
    CieSky sky = makeCieSky(r, sunAt(30));
    ASSERT_TRUE(sky.sun);
    EXPECT_NEAR(sky.solarRadiance * kGenskySunSolidAngle * std::sin(30 * kDegree), 500, 1e-9);
    r.sun = false;
    CieSky noSun = makeCieSky(r, sunAt(30));
    EXPECT_FALSE(noSun.sun);
    EXPECT_DOUBLE_EQ(noSun.groundRadiance, sky.groundRadiance);
    r.solar = {GivenValue::Unit::Radiance, 0};  // -r 0: no sun, and none on the ground
    EXPECT_DOUBLE_EQ(makeCieSky(r, sunAt(30)).groundRadiance, sky.ambientLevel * r.groundReflectance);
}
