// Skies as rendered: the scene text of Brume's gensky and gendaylit, its skybright.cal and perezlum.cal run by
// Brume's .cal evaluator, seen by a view ray to the zenith (-ab 0) and by an upward sensor in an empty scene
// (rtrace -I -ab 1), against the CIE and Perez formulas written out here (not lib/sky's code) and integrated
// over the hemisphere numerically.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "scene_text.h"
#include "sky/hemisphere_quadrature_test.h"

using namespace brume;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180;

// gensky turns luminance into radiance with its sky efficacy, 203 lm/W: zenith luminance fits in kcd/m²
// become W/sr/m² by × 1000 / 203.
constexpr double kKcdToRadiance = 1000.0 / 203;

// Zenith luminance fits (Krochmann & Seidl 1974) that gensky uses, in kcd/m², at sun altitude h: clear sky
// with Linke turbidity 2.45 (gensky's default), overcast, and their mean for the intermediate sky.
double clearZenith(double h) { return (1.376 * 2.45 - 1.81) * std::tan(h) + 0.38; }
double overcastZenith(double h) { return 8.6 * std::sin(h) + 0.123; }

// The sun for `gensky -ang alt az` (degrees, azimuth from south toward west); x east, y north, z up.
struct Sun {
    double altitude;
    glm::dvec3 direction;
};
Sun sunAt(double altitudeDegrees, double azimuthDegrees) {
    double h = altitudeDegrees * kDegree, a = azimuthDegrees * kDegree;
    return {h, {-std::sin(a) * std::cos(h), -std::cos(a) * std::cos(h), std::sin(h)}};
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(a.x * b.x + a.y * b.y + a.z * b.z, -1.0, 1.0));
}

// The CIE clear sky (CIE 110-1994; standard sky 12 of CIE S 011): luminance relative to the zenith's,
// gradation 1 - exp(-0.32 / cos Z) times Kittler's indicatrix 0.91 + 10 exp(-3 χ) + 0.45 cos² χ.
double cieClearRelative(const Sun& sun, const glm::dvec3& d) {
    auto indicatrix = [](double chi) { return 0.91 + 10 * std::exp(-3 * chi) + 0.45 * std::pow(std::cos(chi), 2); };
    auto gradation = [](double cosZ) { return 1 - std::exp(-0.32 / cosZ); };
    return indicatrix(angleBetween(sun.direction, d)) * gradation(d.z) /
           (indicatrix(kPi / 2 - sun.altitude) * gradation(1));
}

// Perez et al. (1993) all-weather sky with the coefficients a-e gendaylit printed, scaled by its
// normalisation (perezlum.cal's first argument); perezlum.cal holds cos Z at 0.01 near the horizon.
struct PerezSky {
    double normalisation, a, b, c, d, e;
    double operator()(const Sun& sun, const glm::dvec3& dir) const {
        double gamma = angleBetween(sun.direction, dir);
        return normalisation * (1 + a * std::exp(b / std::max(dir.z, 0.01))) *
               (1 + c * std::exp(d * gamma) + e * std::pow(std::cos(gamma), 2));
    }
};

// skybright.cal and perezlum.cal fade the sky into the ground's radiance toward the horizon: a mean
// weighted by (cos Z + 1.01)^10 and its inverse (11% ground at 6° of altitude, 0.4% at 17°).
double fadedToGround(double sky, double ground, double cosZ) {
    double a = std::pow(cosZ + 1.01, 10), b = 1 / a;
    return (a * sky + b * ground) / (a + b);
}

// ∫ L cos θ dω over the upper hemisphere of a sky L(d) as the .cal files render it, faded into `ground`.
template <class Sky>
double horizontalIrradiance(Sky sky, double ground) {
    return horizontalIntegral([&](const glm::dvec3& d) { return fadedToGround(sky(d), ground, d.z); });
}

// The sun's disc: gensky's 0.5° and gendaylit's 0.533° in diameter.
double discSolidAngle(double diameterDegrees) { return 2 * kPi * (1 - std::cos(diameterDegrees / 2 * kDegree)); }

std::string skyText(const std::string& command) {
    brume_test::Output o = brume_test::runCaptured("PATH=" + std::string(BRUME_BIN_DIR) + ":$PATH " + command,
                                                   brume_test::scratchDir("sky_render"));
    EXPECT_EQ(o.status, 0) << command << "\n" << o.err;
    return o.out;
}

// The reals of the object named `name` in scene text ("void brightfunc skyfunc ... 7 1 9.3 ...").
std::vector<double> realsOf(const std::string& text, const std::string& name) {
    std::istringstream in(text.substr(text.find(" " + name + "\n")));
    std::string id;
    int n;
    in >> id >> n;
    for (std::string s; n-- > 0;) in >> s;
    in >> n;  // integers: none
    in >> n;
    std::vector<double> reals(n);
    for (double& r : reals) in >> r;
    return reals;
}

// gensky's "# Ground ambient level: X" header line: the sky's horizontal irradiance over π.
double groundAmbientLevel(const std::string& text) {
    const std::string key = "Ground ambient level:";
    return std::stod(text.substr(text.find(key) + key.size()));
}

// What Brume renders of a sky: the radiance toward the zenith, and the irradiance of an upward sensor.
struct Rendered {
    double zenith, horizontal;
};

Rendered render(const std::string& skyText) {
    Scene scene = test::sceneFromText(skyText + "skyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n");
    RenderScene renderScene(scene, {});
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = 1;
    s.ambientAccuracy = 0;  // one bounce exactly: the sensor sees the sky and the sun, nothing else
    s.ambientDivisions = 1 << 16;
    Integrator integrator(renderScene, s);
    glm::dvec3 origin(0), up(0, 0, 1);
    return {test::trace(integrator, origin, up, 0).value[0], test::meanIrradiance(integrator, origin, up, 4)};
}

// Tolerances. Zenith: 0.2%, gensky printing four digits and rounding the clear sky's 1 - exp(-0.32) to 0.274
// in its zenith normalisation (0.05%). Horizontal: 0.5%, that plus the sensor's Monte Carlo noise (2^18
// cosine-weighted samples, about 0.1% for the clear sky's circumsolar peak) and the midpoint quadrature's
// error (below 0.01%).
constexpr double kZenith = 0.002;
constexpr double kHorizontal = 0.005;
// Against gensky's header (π × "Ground ambient level", the horizontal irradiance it reports): 1%, its three
// printed digits (up to 0.35%), its polynomial fit of the clear sky's integral (0.3%) and the fade it leaves
// out (0.1-0.3%).
constexpr double kHeader = 0.01;

}  // namespace

// gensky's CIE clear sky without and with its sun: the zenith follows Krochmann's fit, the horizontal
// irradiance is the integral of the CIE distribution scaled to it (and what gensky's header reports), and the
// sun adds its radiance (gensky's clear-atmosphere model, 1.5e9 lm/sr/m² at 208 lm/W dimmed by air mass) over
// its disc times sin h.
TEST(SkyRender, ClearSkyIsTheCieClearSkyAndTheSunAddsItsDisc) {
    Sun sun = sunAt(40, 20);
    double zenith = clearZenith(sun.altitude) * kKcdToRadiance;
    std::string text = skyText("gensky -ang 40 20 -s");
    double ground = realsOf(text, "skyfunc").at(2);
    double sky = horizontalIrradiance([&](const glm::dvec3& d) { return zenith * cieClearRelative(sun, d); }, ground);
    Rendered noSun = render(text);
    EXPECT_NEAR(noSun.zenith / zenith, 1, kZenith);
    EXPECT_NEAR(noSun.horizontal / sky, 1, kHorizontal);
    EXPECT_NEAR(noSun.horizontal / (kPi * groundAmbientLevel(text)), 1, kHeader);

    double solarRadiance = 1.5e9 / 208 * (1.147 - 0.147 / std::sin(sun.altitude));
    double withSun = sky + solarRadiance * discSolidAngle(0.5) * std::sin(sun.altitude);
    EXPECT_NEAR(render(skyText("gensky -ang 40 20 +s")).horizontal / withSun, 1, kHorizontal);
}

// Overcast (Moon & Spencer, CIE 1955: L = Lz (1 + 2 cos Z) / 3) and uniform skies, both with the overcast
// zenith fit; the overcast sky gives what gensky's header reports. Without the fade into the ground their
// horizontal irradiances would be 7π/9 and π times the zenith radiance; the fade takes 0.14% and 0.34% off.
TEST(SkyRender, OvercastAndUniformSkiesFollowTheirFormulas) {
    double h = 35 * kDegree, zenith = overcastZenith(h) * kKcdToRadiance;
    std::string text = skyText("gensky -ang 35 0 -c");
    double ground = realsOf(text, "skyfunc").at(2);
    Rendered overcast = render(text);
    EXPECT_NEAR(overcast.zenith / zenith, 1, kZenith);
    double moonSpencer = horizontalIrradiance([&](const glm::dvec3& d) { return zenith * (1 + 2 * d.z) / 3; }, ground);
    EXPECT_NEAR(overcast.horizontal / moonSpencer, 1, kHorizontal);
    EXPECT_NEAR(overcast.horizontal / (kPi * groundAmbientLevel(text)), 1, kHeader);
    EXPECT_NEAR(moonSpencer / (7 * kPi / 9 * zenith), 0.9986, 0.0005);

    text = skyText("gensky -ang 35 0 -u");
    ground = realsOf(text, "skyfunc").at(2);
    Rendered uniform = render(text);
    EXPECT_NEAR(uniform.zenith / zenith, 1, kZenith);
    double even = horizontalIrradiance([&](const glm::dvec3&) { return zenith; }, ground);
    EXPECT_NEAR(uniform.horizontal / even, 1, kHorizontal);
    EXPECT_NEAR(even / (kPi * zenith), 0.9966, 0.0005);
}

// The intermediate sky (Radiance's, after Matsuura) is no CIE formula; its zenith is the mean of the clear and
// overcast fits, and its horizontal irradiance what gensky's header reports (π × ground ambient level), to
// 2.5%: gensky's polynomial fit of the integral is off by up to 2.1% below 80° of altitude, and the header
// prints three digits.
TEST(SkyRender, IntermediateSkyGivesTheIrradianceGenskyReports) {
    for (double altitude : {20.0, 50.0}) {
        double h = altitude * kDegree, zenith = (clearZenith(h) + overcastZenith(h)) / 2 * kKcdToRadiance;
        std::string text = skyText("gensky -ang " + std::to_string(altitude) + " -30 -i");
        Rendered r = render(text);
        EXPECT_NEAR(r.zenith / zenith, 1, kZenith) << altitude;
        EXPECT_NEAR(r.horizontal / (kPi * groundAmbientLevel(text)), 1, 0.025) << altitude;
    }
}

// gendaylit's Perez sky for 600 W/m² direct normal and 150 W/m² diffuse horizontal, in W/m² (-O 1): the
// zenith and the horizontal integral follow the Perez formula with the coefficients it printed (tolerances as
// above); the diffuse part gives back the 150 W/m² asked for to 2% (gendaylit normalises with a 145-point sum
// of its own, not the integral, and ignores the fade: 1.6% off for this sky), the sun 600 sin h to 0.5%.
TEST(SkyRender, PerezSkyFollowsItsFormulaAndGivesBackTheIrradiances) {
    Sun sun = sunAt(44, -3.3);
    std::string sunless = skyText("gendaylit -ang 44 -3.3 -W 600 150 -O 1 -s");
    std::vector<double> a = realsOf(sunless, "skyfunc");
    ASSERT_EQ(a.size(), 10u);
    PerezSky perez{a[0], a[2], a[3], a[4], a[5], a[6]};
    double integral = horizontalIrradiance([&](const glm::dvec3& d) { return perez(sun, d); }, a[1]);
    Rendered sky = render(sunless);
    EXPECT_NEAR(sky.zenith / perez(sun, {0, 0, 1}), 1, kZenith);
    EXPECT_NEAR(sky.horizontal / integral, 1, kHorizontal);
    EXPECT_NEAR(sky.horizontal / 150, 1, 0.02);

    Rendered withSun = render(skyText("gendaylit -ang 44 -3.3 -W 600 150 -O 1"));
    EXPECT_NEAR((withSun.horizontal - sky.horizontal) / (600 * std::sin(sun.altitude)), 1, kHorizontal);
}
