// Flames light the room: smoke with a temperature grid is a light source that next-event estimation samples
// (integrator/flame_lights.h), at -ab 0 as at any -ab, against closed forms and numerical integrals of the
// black body's light through the flame. The flame is a cube of even smoke [0, 1.99]³ (voxels of 1 cm, the
// density ramping to 0 within a voxel outside), which emits and absorbs as a cube [−0.005, 1.995]³ would: the
// references use that cube. Values per band against Brume's own black body (FlamesGlowAsBlackBodies checks it
// against Planck's law); sensors and views in a scene with nothing else, so that every value is the flame's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_forms.h"
#include "integrator/testing.h"
#include "medium/testing.h"
#include "ray_path_dir.h"
#include "scene_text.h"
#include "spectral_sampling_scope.h"
#include "spectrum/blackbody.h"
#include "spectrum/cie_tables.h"
#include "spectrum/colorimetry.h"

namespace brume {
namespace {

using integrator_testing::Mean;
using namespace medium::testing;

constexpr double kKelvin = 1500;
const Bounds3 kCube{dvec3(-0.005), dvec3(1.995)};

// The flame's grids in `file`: density 1, and `kelvin` wherever there is smoke (its ramp included), or with
// `edge` over the density's voxels only, so that both ramp together at the flame's faces.
void writeFlame(const RayPathDir& dir, double kelvin = kKelvin, const std::string& file = "flame.vdb", bool edge = false) {
    auto density = boxGrid({0, 0, 0}, {199, 199, 199}, 1.0f, 0.01);
    int reach = edge ? 0 : 2;
    auto temperature = boxGrid({-reach, -reach, -reach}, {199 + reach, 199 + reach, 199 + reach}, float(kelvin), 0.01);
    density->setName("density"), temperature->setName("temperature");
    openvdb::io::File((dir.path() / file).string()).write({density, temperature});
}

// 683 lm/W · ∫ B ȳ dλ, Planck's law against the CIE's 1 nm table: a black body's luminance (cd/m²).
double planckLuminance(double kelvin) {
    double sum = 0;
    for (double nm = 360; nm <= 830; nm += 1) sum += 683.002 * planck(nm, kelvin) * cieY().at(nm);
    return sum;
}

// The flame as a smoke of extinction k per unit density and albedo 0 read from `file`, then `extra` scene text.
std::string flameScene(double k, const std::string& file, const std::string& extra) {
    std::string ks = std::to_string(k);
    return "void smoke f 2 temperature=temperature " + file + " 0 3 " + ks + " " + ks + " " + ks + "\n" + extra;
}

// The same from flame.vdb.
std::string flameScene(double k, const std::string& extra = "") { return flameScene(k, "flame.vdb", extra); }

// The length of the line from p along unit dir inside the cube.
double chord(const dvec3& p, const dvec3& dir) {
    double t0 = 0, t1 = std::numeric_limits<double>::infinity();
    return clipToBox(kCube, p, dir, t0, t1) ? t1 - t0 : 0;
}

// The mean of `runs` irradiance estimates at p facing n, in band c, with its standard error.
Mean irradiance(const Integrator& integrator, const dvec3& p, const dvec3& n, int runs, int c = 0) {
    Mean m;
    for (int i = 0; i < runs; ++i) m.add(test::irradiance(integrator, p, n, uint64_t(i)).value[c]);
    return m;
}

// Optically thick (τ = 1000 across): the face the sensor sees radiates as a black body, so E = π B F, F the
// configuration factor of the 2 × 2 m face 1.5 m away (the sensor on its axis: four corner factors). 1.5%:
// the face's edges are where the ramping density gets thick, within 4 mm of the reference cube's (0.4% of F),
// and four standard errors of the mean (measured 0.3%).
TEST(Flames, ThickFlameFaceOnRadiatesAsABlackBody) {
    RayPathDir dir;
    writeFlame(dir);
    test::TestScene t(flameScene(500));
    Integrator integrator(t.render, test::fixedSeed());
    const dvec3 sensor(0.995, -1.5, 0.995);
    double factor = 4 * test::cornerFormFactor(1, 1, 1.495);
    Spectrum b = blackbody(kKelvin);
    for (int c = 0; c < 3; ++c) {
        Mean e = irradiance(integrator, sensor, dvec3(0, 1, 0), 40, c);
        double expected = std::numbers::pi * b[c] * factor;
        EXPECT_NEAR(e.value(), expected, 0.011 * expected + 4 * e.standardError()) << "band " << c;
    }
}

// A view ray face-on through the cube (2 m of smoke, τ = 2K) sees B (1 − e^{−2K}), Planck's luminance, on every
// ray, thin or thick: each of 16 rays (over the face's middle) within 0.5 % of Planck in 41 bands (the bands'
// averages of ȳ; measured 0.24 %) and 1 % in RGB (the colour's conversion; measured 0.03 %), at 1500 and 2000 K
// and K from 0.5 to 500 /m (the flame's light then comes from the first millimetres, where the density ramps
// inside the voxel at its face: draws by the majorant's exponential there gave −27 to −92 % means and 400 %
// spreads per ray at K 50).
TEST(Flames, EvenFlamesAreBlackBodiesOfTheirDepthOnEveryRay) {
    RayPathDir dir;
    for (double kelvin : {1500.0, 2000.0}) writeFlame(dir, kelvin, "flame" + std::to_string(int(kelvin)) + ".vdb");
    for (int bands : {3, 41}) {
        SpectralSamplingScope sampling(bands);
        for (double kelvin : {1500.0, 2000.0})
            for (double k : {0.5, 5.0, 50.0, 500.0}) {
                test::TestScene t(flameScene(k, "flame" + std::to_string(int(kelvin)) + ".vdb", ""));
                Integrator integrator(t.render, test::fixedSeed());
                const double expected = planckLuminance(kelvin) * -std::expm1(-2 * k);
                for (int i = 0; i < 16; ++i) {
                    dvec3 from(0.6 + 0.25 * (i % 4), -1, 0.6 + 0.25 * (i / 4));
                    double v = 179 * photopic(test::trace(integrator, from, dvec3(0, 1, 0), uint64_t(i)).value);
                    EXPECT_NEAR(v, expected, (bands == 3 ? 0.01 : 0.005) * expected)
                        << bands << " bands, " << kelvin << " K, K " << k << ", ray " << i;
                }
            }
    }
}

// At the flame's face, density and temperature ramp together across a voxel (trilinear, from 0 and 0 K at
// x = −0.01 to 1 and 1500 K at 0): B falls by 30 orders of magnitude where the smoke thins. Along x through
// the cube, ∫ σ B(T) e^{−τ} dx by the midpoint rule (4000 points a ramp, Brume's black body at each T; the
// plateau in closed form): the mean of 64 rays within 1 % and 4 standard errors, no value negative, in RGB and
// 41 bands, thin to thick; the spread of one ray under 6 % and no ray above 1.2× the mean: no tail (measured
// 3.8 % and 1.09× at K 500, where all the light comes from within the ramp and B climbs 30 orders of magnitude
// there, 2.5-2.8 % at K 5 and 50; with 8 points in place of 16, 6.4 % and 1.14×; with the draws by optical depth
// alone 33 % and 1.33×; by the majorant's exponential, means −27 to −92 % off).
TEST(Flames, AnEdgeWhereDensityAndTemperatureRampTogetherMatchesAnIntegralAlongTheRay) {
    RayPathDir dir;
    writeFlame(dir, kKelvin, "edge.vdb", true);
    for (int bands : {3, 41}) {
        SpectralSamplingScope sampling(bands);
        for (double k : {5.0, 50.0, 500.0}) {
            // Ramps over [−0.01, 0] (up) and [1.99, 2] (down); the plateau between at 1 and kKelvin.
            const int n = 4000;
            const double h = 0.01 / n, rampDepth = k * 0.005, plateau = k * 1.99;
            double up = 0, down = 0;
            for (int i = 0; i < n; ++i) {
                double rho = (i + 0.5) / n;  // in the first ramp, rising
                double tau = k * 0.01 * rho * rho / 2;
                up += k * rho * photopic(blackbody(kKelvin * rho)) * std::exp(-tau) * h;
                double fall = 1 - rho, tauDown = rampDepth + plateau + k * 0.01 * (rho - rho * rho / 2);
                down += k * fall * photopic(blackbody(kKelvin * fall)) * std::exp(-tauDown) * h;
            }
            double middle = photopic(blackbody(kKelvin)) * std::exp(-rampDepth) * -std::expm1(-plateau);
            const double expected = 179 * (up + middle + down);
            test::TestScene t(flameScene(k, "edge.vdb", ""));
            Integrator integrator(t.render, test::fixedSeed());
            Mean m;
            double most = 0;
            for (int i = 0; i < 64; ++i) {
                Spectrum v = test::trace(integrator, dvec3(-1, 0.995, 0.995), dvec3(1, 0, 0), uint64_t(i)).value;
                for (int c = 0; c < v.size(); ++c) EXPECT_GE(v[c], 0) << "band " << c;
                double y = 179 * photopic(v);
                m.add(y), most = std::max(most, y);
            }
            SCOPED_TRACE(std::to_string(bands) + " bands, K " + std::to_string(k));
            EXPECT_NEAR(m.value(), expected, 0.01 * expected + 4 * m.standardError());
            EXPECT_LT(m.standardError() * 8 / m.value(), 0.06);  // one ray's spread: √64 standard errors
            EXPECT_LT(most, 1.2 * m.value());
        }
    }
}

// Kirchhoff inside an isothermal flame: from the middle of the cube (τ = 50 to its faces), albedo .5, a ray sees
// B with every order of scattering (what the smoke does not emit it scatters from smoke as hot), and with n
// orders (-ab n, path tracing) (1 − a^{n+2}) B: the emission (1 − a) B, then each order a times the one before.
// -ab 0: 64 rays, the mean within 1 % and 4 standard errors and one ray's spread under 10 % (measured 7-8 %:
// the in-scattered light at 8 points, each sampling the flame around it); -ab 1: 500 rays (a spread of 34 %
// a ray, from the phase function's rays), 1 % and 4 standard errors.
TEST(Flames, InsideAnIsothermalScatteringFlameEachOrderAddsAlbedoTimesTheOneBefore) {
    RayPathDir dir;
    writeFlame(dir);
    test::TestScene t("void smoke f 2 temperature=temperature flame.vdb 0 7 50 50 50 .5 .5 .5 0\n");
    const double b = photopic(blackbody(kKelvin)), albedo = 0.5;
    for (int bounces : {0, 1}) {
        RenderSettings s = test::fixedSeed();
        s.ambientBounces = bounces;
        s.ambientAccuracy = 0;
        Integrator integrator(t.render, s);
        Mean m;
        const int rays = bounces == 0 ? 64 : 500;
        for (int i = 0; i < rays; ++i)
            m.add(photopic(test::trace(integrator, dvec3(0.995), glm::normalize(dvec3(0.3, 0.5, 0.81)), uint64_t(i)).value));
        const double expected = (1 - std::pow(albedo, bounces + 2)) * b;
        EXPECT_NEAR(m.value(), expected, 0.01 * expected + 4 * m.standardError()) << "-ab " << bounces;
        if (bounces == 0) {
            EXPECT_LT(m.standardError() * 8 / m.value(), 0.10);
        }
    }
}

// Optically thin (τ = 0.1 across), seen from below and aside: E = ∫ σ B cos θ e^{−σℓ} / d² dV over the cube (ℓ
// its chord toward the sensor), by the midpoint rule on 60³ points (0.1%). At -ab 0 and -ab 2: rays drawn from
// the sensor's Lambertian lobe leave the flame's light to next-event estimation, so the black room adds
// nothing. 1% and four standard errors.
TEST(Flames, ThinFlameMatchesAVolumeIntegral) {
    RayPathDir dir;
    writeFlame(dir);
    const double sigma = 0.05;
    test::TestScene t(flameScene(sigma));
    const dvec3 sensor(-1.2, -1.0, 0.4), normal = glm::normalize(dvec3(1, 1.2, 0.3));
    const int n = 60;
    const double h = 2.0 / n;
    double integral = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                dvec3 x = kCube.lo + h * dvec3(i + 0.5, j + 0.5, k + 0.5), toward = sensor - x;
                double d = glm::length(toward), cosine = glm::dot(normal, -toward / d);
                if (cosine > 0) integral += sigma * cosine * std::exp(-sigma * chord(x, toward / d)) / (d * d);
            }
    integral *= h * h * h;
    Spectrum b = blackbody(kKelvin);
    for (int bounces : {0, 2}) {
        RenderSettings s = test::fixedSeed();
        s.ambientBounces = bounces;
        s.ambientAccuracy = 0;
        s.ambientDivisions = 512;  // enough rays through the flame to see it counted twice
        Integrator integrator(t.render, s);
        Mean e = irradiance(integrator, sensor, normal, 100);
        double expected = b[0] * integral;
        EXPECT_NEAR(e.value(), expected, 0.01 * expected + 4 * e.standardError()) << "-ab " << bounces;
    }
}

// Whatever its density profile, a flame of one temperature and albedo 0 seen from inside sends B (1 − e^{−τ})
// along a ray: here a ramp ρ = x (its cells bound it loosely, so the guard of uniform points is drawn too),
// looked along from x = 1 to its end at 9.9 (and half a voxel of ramp beyond): τ = K ((9.9² − 1)/2 + 0.05·9.9).
// Thin (τ 0.2) and thick (τ 4.9): the mean of 400 rays within 0.3% and four standard errors.
TEST(Flames, UnevenFlameSeenFromInsideIsABlackBodyOfItsDepth) {
    RayPathDir dir;
    auto ramp = boxGrid({0, 0, 0}, {99, 99, 99}, 0.0f, 0.1);
    ramp->tree().voxelizeActiveTiles();
    for (auto it = ramp->tree().beginValueOn(); it; ++it) it.setValue(0.1f * it.getCoord().x());
    auto temperature = boxGrid({-2, -2, -2}, {101, 101, 101}, float(kKelvin), 0.1);
    ramp->setName("density"), temperature->setName("temperature");
    openvdb::io::File((dir.path() / "flame.vdb").string()).write({ramp, temperature});
    Spectrum b = blackbody(kKelvin);
    for (double k : {0.004, 0.1}) {
        test::TestScene t(flameScene(k));
        Integrator integrator(t.render, test::fixedSeed());
        Mean v;
        for (int i = 0; i < 400; ++i) v.add(test::trace(integrator, dvec3(1, 5, 5), dvec3(1, 0, 0), uint64_t(i)).value[0]);
        double expected = b[0] * -std::expm1(-k * ((9.9 * 9.9 - 1) / 2 + 0.05 * 9.9));
        EXPECT_NEAR(v.value(), expected, 0.003 * expected + 4 * v.standardError()) << "K " << k;
    }
}

// A wall between the flame and the sensor: no light at all, not a little noise.
TEST(Flames, AFlameBehindAWallLightsNothingThere) {
    RayPathDir dir;
    writeFlame(dir);
    test::TestScene t(flameScene(0.05, "void plastic white 0 0 5 .8 .8 .8 0 0\n"
                                       "white polygon wall 0 0 12  -3 -.5 -3  -3 -.5 5  5 -.5 5  5 -.5 -3\n"));
    Integrator integrator(t.render, test::fixedSeed());
    for (int i = 0; i < 20; ++i)
        EXPECT_EQ(test::irradiance(integrator, dvec3(1, -1, 1), dvec3(0, 1, 0), uint64_t(i)).value[0], 0) << i;
    EXPECT_GT(test::irradiance(integrator, dvec3(1, -0.4, 1), dvec3(0, 1, 0), 0).value[0], 0);
}

// A rough metal facing the flame, seen at 45°: its radiance is ∫ f cos θ L dω, L = B (1 − e^{−σℓ}) along each
// direction, whatever share next-event estimation and the rays drawn from its glossy lobe each take of it
// (power heuristic). Against the integral over the hemisphere (midpoint rule, 400 × 800 cells) of the lobes
// the material gives the hit: 1.5% and four standard errors.
TEST(Flames, GlossyReflectionSharesTheFlameBetweenSamplesAndRays) {
    RayPathDir dir;
    writeFlame(dir);
    const double sigma = 0.3;
    test::TestScene t(flameScene(sigma, "void metal m 0 0 5 .8 .8 .8 .9 .15\n"
                                        "m polygon panel 0 0 12  -2 -1.5 -2  -2 -1.5 4  4 -1.5 4  4 -1.5 -2\n"));
    Integrator integrator(t.render, test::fixedSeed());
    const dvec3 eye(-0.5, -0.5, 1), point(0.5, -1.5, 1), view = glm::normalize(point - eye), up(0, 1, 0);
    int material = -1;
    for (size_t i = 0; i < t.scene.objects.size(); ++i)
        if (t.scene.objects[i].name == "m") material = int(i);
    Shading sh = integrator_testing::flatHit(point, up, view);
    Lobes lobes;
    ASSERT_TRUE(t.render.material(material)->scatter(sh, lobes));
    Scatterer metal(sh, lobes);
    Spectrum b = blackbody(kKelvin);
    double expected = b[0] * integrator_testing::overDirections(
                                 [&](const dvec3& l) {
                                     return metal.response(l, 0)[0] * -std::expm1(-sigma * chord(point, l));
                                 },
                                 up, 400);
    Mean v;
    for (int i = 0; i < 400; ++i) v.add(test::trace(integrator, eye, view, uint64_t(i)).value[0]);
    EXPECT_NEAR(v.value(), expected, 0.015 * expected + 4 * v.standardError());
}

// Fog (albedo .9, g .6, τ = 0.02 across) above the flame, seen against nothing: the flame's light it scatters
// toward the eye, at -ab 0 by next-event estimation alone, at -ab 1 shared by the power heuristic with rays drawn
// from the phase function, which add the fog's second scattering too (about τ/2 of the first, 1%): the two agree
// within 1.5% and four standard errors of their difference.
TEST(Flames, PhaseFunctionRaysShareTheFlameWithSamples) {
    RayPathDir dir;
    writeFlame(dir);
    writeGrid(dir.path() / "fog.vdb", boxGrid({250, 200, 0}, {449, 319, 199}, 1.0f, 0.01));
    test::TestScene t(flameScene(1, "void smoke fog 1 fog.vdb 0 7 .01 .01 .01 .9 .9 .9 .6\n"));
    const dvec3 eye(6, 2.6, 1), view(-1, 0, 0);
    Mean by[2];
    for (int bounces : {0, 1}) {
        RenderSettings s = test::fixedSeed();
        s.ambientBounces = bounces;
        Integrator integrator(t.render, s);
        for (int i = 0; i < 400; ++i) by[bounces].add(test::trace(integrator, eye, view, uint64_t(i)).value[0]);
    }
    double se = std::hypot(by[0].standardError(), by[1].standardError());
    EXPECT_GT(by[0].value(), 0);
    EXPECT_NEAR(by[1].value(), by[0].value(), 0.015 * by[0].value() + 4 * se);
}

}  // namespace
}  // namespace brume
