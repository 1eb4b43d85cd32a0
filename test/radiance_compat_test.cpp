// Brume against Radiance 6.1's rtrace at -ab 0, end to end: test/data/radiance/materials.rad (a room with
// every material, emitter and surface type Brume has), the rays and sensor points beside it, and the
// values Radiance computed for them (make_reference.sh; README.md there says how and why those options).
//
// Brume runs with the same options but averages many independent estimates of each ray, so its answer is
// the exact integral to within ~0.2%; Radiance's is deterministic and close to exact by construction of the
// scene (small sources, -ds 0.02, -dj 0, -dt 0). What remains between them is listed in README.md.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "integrator/integrator.h"
#include "scene/reader.h"
#include "scene_text.h"

using namespace brume;

namespace {

const std::string kRoom = std::string(BRUME_TEST_DATA) + "/radiance/";
const std::string kInstances = std::string(BRUME_TEST_DATA) + "/radiance_instances/";
const std::string kPatterns = std::string(BRUME_TEST_DATA) + "/patterns/";
const std::string kText = std::string(BRUME_TEST_DATA) + "/text/";
const std::string kBsdf = std::string(BRUME_TEST_DATA) + "/bsdf/";
const std::string kMaterials = std::string(BRUME_TEST_DATA) + "/material_functions/";
const std::string kOffice = std::string(BRUME_TEST_DATA) + "/office/";

using Rgb = std::array<double, 3>;

struct LabelledRay {
    std::string label;
    dvec3 org, dir;
};

// "label x y z dx dy dz" lines; '#' starts a comment line.
std::vector<LabelledRay> readRays(const std::string& dir, const std::string& name) {
    std::ifstream in(dir + name);
    EXPECT_TRUE(in) << "cannot open " << name;
    std::vector<LabelledRay> rays;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        LabelledRay r;
        s >> r.label >> r.org.x >> r.org.y >> r.org.z >> r.dir.x >> r.dir.y >> r.dir.z;
        EXPECT_TRUE(s) << name << ": bad line '" << line << "'";
        rays.push_back(r);
    }
    return rays;
}

// "label v1 v2 ..." lines: the values after the label (three, or six with standard errors).
std::map<std::string, std::vector<double>> readReference(const std::string& dir, const std::string& name) {
    std::ifstream in(dir + name);
    EXPECT_TRUE(in) << "cannot open " << name;
    std::map<std::string, std::vector<double>> values;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        std::string label;
        s >> label;
        for (double v; s >> v;) values[label].push_back(v);
    }
    return values;
}

// make_reference.sh's deterministic options: -ab 0 -av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02
// -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5 -u-.
RenderSettings referenceSettings(double specularThreshold = 1) {
    RenderSettings s;
    s.ambientBounces = 0;
    s.ambientValue = Spectrum(0.1f);
    s.ambientWeight = 0;
    s.directThreshold = 0;
    s.directCertainty = 1;
    s.sourceJitter = 0;
    // Radiance subdivides flat and cylindrical sources by this ratio; for Brume it sets how many stratified
    // samples each source gets per estimate (up to 64), which only lowers the noise.
    s.sourceSubdivision = 0.02;
    s.directRelays = 0;
    s.directVisible = true;
    s.materials.backVisible = true;
    s.materials.specularThreshold = specularThreshold;
    s.specularJitter = 1;
    s.maxReflections = 12;
    s.minWeight = 1e-5;
    s.randomSampling = false;
    return s;
}

// A scene file of `dir`, the files it places (and function files, data files, pictures) found there.
Scene sceneIn(const std::string& dir, const std::string& file) {
    test::ScopedRayPath path(dir.c_str());
    return loadScene({dir + file});
}

const Scene& room() {
    static const Scene scene = sceneIn(kRoom, "materials.rad");
    return scene;
}

// The mean of `runs` independent estimates of each ray (its value, or irradiance for sensors); with `batches`
// > 1, the median of the means of that many batches of them (see DaylitOfficeAgreesWithRadiance).
enum class Mode { View, Sensor, IrradianceAtHit };  // rtrace, rtrace -I, rtrace -i

std::vector<Rgb> brumeMeans(const Scene& scene, const std::vector<LabelledRay>& rays, Mode mode, int runs,
                            const RenderSettings& s, std::vector<Rgb>* standardErrors = nullptr, int batches = 1) {
    RenderScene render(scene, s.materials);
    Integrator integrator(render, s);
    std::vector<Rgb> mean(rays.size()), sem(rays.size());
    tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
        Rgb sum{}, sum2{};
        std::vector<Rgb> batchSums(batches, Rgb{});
        for (int k = 0; k < runs; ++k) {
            uint64_t index = uint64_t(i) * uint64_t(runs) + uint64_t(k);
            RayRecord r = mode == Mode::Sensor            ? test::irradiance(integrator, rays[i].org, rays[i].dir, index)
                          : mode == Mode::IrradianceAtHit ? test::irradianceAtHit(integrator, rays[i].org, rays[i].dir, index)
                                                          : test::trace(integrator, rays[i].org, rays[i].dir, index);
            for (int c = 0; c < 3; ++c) {
                sum[c] += r.value[c], sum2[c] += double(r.value[c]) * r.value[c];
                batchSums[k % batches][c] += r.value[c];
            }
        }
        for (int c = 0; c < 3; ++c) {
            std::vector<double> totals(batches);
            for (int b = 0; b < batches; ++b) totals[b] = batchSums[b][c];
            std::sort(totals.begin(), totals.end());
            mean[i][c] = 0.5 * (totals[(batches - 1) / 2] + totals[batches / 2]) * batches / runs;  // one: the mean
            double all = sum[c] / runs;
            sem[i][c] = std::sqrt(std::max(0.0, sum2[c] / runs - all * all) / runs);
        }
    });
    if (standardErrors) *standardErrors = sem;
    return mean;
}

// Relative difference of one channel; two values that are both (near) zero agree.
double relative(double brume, double radiance) {
    double scale = std::max(std::abs(brume), std::abs(radiance));
    return scale < 1e-9 ? 0.0 : (brume - radiance) / scale;
}

struct Comparison {
    double sumSquares = 0;
    int count = 0;
    double rms() const { return count ? std::sqrt(sumSquares / count) : 0.0; }
};

// Compares Brume's means with the reference, ray by ray; returns the RMS over all channels of all rays.
// With BRUME_COMPAT_VERBOSE set, prints every ray that differs by more than 1% in some channel.
Comparison compare(const std::vector<LabelledRay>& rays, const std::vector<Rgb>& brume,
                   const std::map<std::string, std::vector<double>>& reference, double perRayBound,
                   const std::set<std::string>& only = {}) {
    Comparison c;
    for (size_t i = 0; i < rays.size(); ++i) {
        const std::string& label = rays[i].label;
        if (!only.empty() && !only.count(label)) continue;
        auto it = reference.find(label);
        if (it == reference.end() || it->second.size() < 3) {
            ADD_FAILURE() << "no reference value for " << label;
            continue;
        }
        if (std::getenv("BRUME_COMPAT_VERBOSE")) {
            double worst = 0;
            for (int ch = 0; ch < 3; ++ch)
                if (std::abs(relative(brume[i][ch], it->second[ch])) > std::abs(worst))
                    worst = relative(brume[i][ch], it->second[ch]);
            if (std::abs(worst) > 0.01)
                std::printf("  %-26s Radiance %10.4g %10.4g %10.4g  Brume %10.4g %10.4g %10.4g  %+.2f%%\n",
                            label.c_str(), it->second[0], it->second[1], it->second[2], brume[i][0], brume[i][1],
                            brume[i][2], 100 * worst);
        }
        for (int ch = 0; ch < 3; ++ch) {
            double d = relative(brume[i][ch], it->second[ch]);
            c.sumSquares += d * d;
            ++c.count;
            EXPECT_LT(std::abs(d), perRayBound) << label << " channel " << ch << ": Brume " << brume[i][ch]
                                                << ", Radiance " << it->second[ch];
        }
    }
    return c;
}

// Per ray: 3%. Brume's means carry ~0.2% noise; the rest is Radiance's approximations, which the scene keeps
// small but not zero: ≤ 64 cells per flat or cylindrical source evaluated at their centres, sphere sources
// and the sun seen as one direction (their centre), rough-specular highlights evaluated at those directions
// with a lobe widened by the cell's solid angle, cylinders sampled on their axis (worst here: ~2%, the
// glow's highlight on the brushed column and the tube's on the brushed sheet). Over all rays: RMS 1%.
constexpr double kPerRay = 0.03;
constexpr double kRms = 0.01;
constexpr int kRuns = 128;  // estimates averaged per ray

}  // namespace

// Brume's means for the rays of `rayFile` against Radiance's values in `referenceFile`: each ray within
// `perRay`, all within kRms.
void expectAgreement(const std::string& dir, const Scene& scene, const char* rayFile, size_t atLeast, Mode mode,
                     const char* referenceFile, double perRay = kPerRay, int runs = kRuns,
                     const RenderSettings& settings = referenceSettings(), double rms = kRms, int batches = 1) {
    auto rays = readRays(dir, rayFile);
    ASSERT_GE(rays.size(), atLeast);
    auto brume = brumeMeans(scene, rays, mode, runs, settings, nullptr, batches);
    Comparison c = compare(rays, brume, readReference(dir, referenceFile), perRay);
    EXPECT_LT(c.rms(), rms) << "over " << c.count << " channel values";
    if (std::getenv("BRUME_COMPAT_VERBOSE")) std::printf("  RMS %.3f%% over %d values\n", 100 * c.rms(), c.count);
}

// test/data/patterns: every pattern, texture and mixture type with .cal files (Brume's evaluator reading
// files written for Radiance), data files and a picture, on floor panels under the sun, a patterned luminaire
// and a patterned sky. Tolerances as above; there are no penumbrae at the rays, so the agreement is closer.
TEST(RadianceCompat, PatternsTexturesAndMixturesAgreeWithRadiance) {
    // rays.txt: 118 view rays; 8 estimates each suffice, the scene's direct light being nearly exact.
    test::ScopedRayPath path(kPatterns.c_str());  // the function files, data files and picture are there
    Scene scene = loadScene({kPatterns + "patterns.rad"});
    expectAgreement(kPatterns, scene, "rays.txt", 110, Mode::View, "reference.txt", kPerRay, 8);
}

// test/data/text: brighttext, colortext and mixtext, with inline text and a text file, the three spacing
// rules, a slanted frame, a mixture with void, Brume's helvet.fnt (which make_reference.sh gives Radiance
// too) and a tiny font of the test's own. No ray lies near a glyph's edge (make_rays.sh): each within 1%.
TEST(RadianceCompat, TextPatternsAndMixturesAgreeWithRadiance) {
    test::ScopedRayPath path(kText.c_str());  // helvet.fnt is not there: Brume's embedded one is read
    Scene scene = loadScene({kText + "text.rad"});
    expectAgreement(kText, scene, "rays.txt", 90, Mode::View, "reference.txt", 0.01, 8);
}

// test/data/material_functions: the anisotropic materials (u by constants, by functions in transformed
// frames, along the normal, under a pattern and a texture) and the materials with specular functions and
// data of the light direction, their specular parts as direct light (-st 1). Each ray within 1%: small
// sphere sources, no penumbrae.
TEST(RadianceCompat, AnisotropicAndFunctionMaterialsAgreeWithRadiance) {
    test::ScopedRayPath path(kMaterials.c_str());
    Scene scene = loadScene({kMaterials + "scene.rad"});
    expectAgreement(kMaterials, scene, "rays.txt", 130, Mode::View, "reference.txt", 0.01, 16);
}

TEST(RadianceCompat, ViewRaysAgreeWithRadianceForEveryMaterial) {
    expectAgreement(kRoom, room(), "rays.txt", 90, Mode::View, "reference_rays.txt");  // rays.txt: 99 view rays
}

// rtrace -i: irradiance where each view ray first meets an opaque surface, sources at their radiance.
TEST(RadianceCompat, IrradianceAtFirstOpaqueHitAgreesWithRadiance) {
    expectAgreement(kRoom, room(), "rays.txt", 90, Mode::IrradianceAtHit, "reference_irradiance_at_hit.txt");
}

TEST(RadianceCompat, SensorIrradianceAgreesWithRadiance) {
    expectAgreement(kRoom, room(), "sensors.txt", 60, Mode::Sensor, "reference_sensors.txt");  // sensors.txt: 70 points
}

// Brume's means of `runs` estimates per ray against a Monte Carlo reference of Radiance's (mean and standard
// error per channel): within 4 combined standard errors (chance) plus `relative` of the value.
void expectWithinNoise(const Scene& scene, const std::vector<LabelledRay>& rays, Mode mode, int runs,
                       const RenderSettings& settings, std::map<std::string, std::vector<double>>& reference,
                       double relative) {
    std::vector<Rgb> sem;
    auto brume = brumeMeans(scene, rays, mode, runs, settings, &sem);
    Comparison all;
    bool verbose = std::getenv("BRUME_COMPAT_VERBOSE");
    for (size_t i = 0; i < rays.size(); ++i) {
        const auto& ref = reference[rays[i].label];
        ASSERT_EQ(ref.size(), 6u) << rays[i].label;
        for (int c = 0; c < 3; ++c) {
            double sigma = std::hypot(ref[3 + c], sem[i][c]);
            EXPECT_NEAR(brume[i][c], ref[c], 4 * sigma + relative * ref[c])
                << rays[i].label << " channel " << c << " (σ " << sigma << ")";
            double d = ::relative(brume[i][c], ref[c]);
            all.sumSquares += d * d;
            ++all.count;
        }
        if (verbose)
            std::printf("  %-24s Radiance %10.4g ± %-8.2g Brume %10.4g ± %-8.2g %+.2f%%\n", rays[i].label.c_str(), ref[0],
                        ref[3], brume[i][0], sem[i][0], 100 * ::relative(brume[i][0], ref[0]));
    }
    if (verbose) std::printf("  RMS %.2f%% over %d values\n", 100 * all.rms(), all.count);
}

// Rough specular surfaces above -st 0.15 (metal spec 0.9, plastic spec 0.2) reflect by sampled rays. The
// reference is Radiance's own Monte Carlo mean of 4000 rays each (-ss 1 -u-), with its standard error.
// Tolerance: 4 combined standard errors (chance) plus 2.5% of the value (Radiance's highlight
// approximations above, the same as in the deterministic runs).
TEST(RadianceCompat, SampledGlossyReflectionAgreesWithRadianceMonteCarlo) {
    auto all = readRays(kRoom, "rays.txt");
    auto reference = readReference(kRoom, "reference_glossy.txt");
    std::vector<LabelledRay> rays;
    for (const auto& r : all)
        if (reference.count(r.label)) rays.push_back(r);
    ASSERT_GE(rays.size(), 7u);
    expectWithinNoise(room(), rays, Mode::View, 4000, referenceSettings(0.15), reference, 0.025);
}

// test/data/radiance_instances: a compiled mesh with smooth normals, uv and two materials, placed with its
// materials and with a modifier, scaled, mirrored and rotated; an octree placed by instances with and without
// a modifier, mirrored; instances within an instance. Its README.md says how the references were made.
// Each ray within 1%: these scenes keep Radiance's approximations out (see make_reference.sh).
TEST(RadianceCompat, MeshesAndInstancesAgreeWithRadiance) {
    Scene scene = sceneIn(kInstances, "scene.rad");
    expectAgreement(kInstances, scene, "rays.txt", 25, Mode::View, "reference_rays.txt", 0.01);
    expectAgreement(kInstances, scene, "sensors.txt", 10, Mode::Sensor, "reference_sensors.txt", 0.01);
}

// Patterns and textures in placed objects (test/data/radiance_instances/patterned.rad): an octree's own
// patterns work in its coordinates wherever instances put it, an instance's patterned modifier in the frame of
// the instance, a mesh's (u, v) reach patterns as Lu, Lv, and a texture adds to a mesh's vertex normals.
// Each ray within 1%, as above.
TEST(RadianceCompat, PatternsInInstancesAndMeshesAgreeWithRadiance) {
    test::ScopedRayPath path(kInstances.c_str());  // RenderScene compiles the patterns: keep RAYPATH until done
    Scene scene = loadScene({kInstances + "patterned.rad"});
    expectAgreement(kInstances, scene, "patterned_rays.txt", 20, Mode::View, "reference_patterned.txt", 0.01, 16);
}

// The same scene with the Wavefront file in place of the mesh obj2mesh compiled from it (its usemtl names
// taking the materials obj2mesh was given) gives the same values: the faces split along the same diagonals,
// normals and (u, v) as obj2mesh makes them.
TEST(RadianceCompat, WavefrontMeshAgreesWithItsCompiledMesh) {
    auto contents = [](const std::string& file) {
        std::ifstream in(kInstances + file);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    std::string text = contents("materials.rad") + contents("scene.rad");
    for (size_t at; (at = text.find("vault.rtm")) != std::string::npos;) text.replace(at, 9, "vault.obj");
    test::ScopedRayPath path(kInstances.c_str());
    Scene scene = test::sceneFromText(text);
    expectAgreement(kInstances, scene, "rays.txt", 25, Mode::View, "reference_rays.txt", 0.01);
}

// test/data/bsdf: a skylight with a Klems BSDF (prism_quarter.xml) over a floor, under the sun; README.md there
// says what and how. The references are means of Radiance's noisy estimates with their standard errors.
RenderSettings bsdfSettings(int ambientBounces) {
    RenderSettings s = referenceSettings(0.15);
    s.ambientValue = Spectrum(0.f);
    s.ambientAccuracy = 0;
    s.ambientBounces = ambientBounces;
    s.ambientDivisions = 1024;
    s.maxReflections = 8;
    s.minWeight = 1e-6;
    return s;
}

// View rays into the transmitted and reflected sun: 5% beyond the noise, for the peaks, where Radiance's
// handful of jittered views per ray meet Brume's 16 stratified ones (README.md).
TEST(RadianceCompat, BsdfViewRaysAgreeWithRadiance) {
    test::ScopedRayPath path(kBsdf.c_str());  // the BSDF file is read when rendering starts
    Scene scene = sceneIn(kBsdf, "scene.rad");
    auto reference = readReference(kBsdf, "reference_rays.txt");
    expectWithinNoise(scene, readRays(kBsdf, "rays.txt"), Mode::View, 256, bsdfSettings(0), reference, 0.05);
}

// Floor sensors: at -ab 0 the pane casts a full shadow (Radiance's thin BSDF surfaces stop shadow rays); at
// -ab 1 the sun comes through it, found by next-event estimation where floor paths meet the pane.
TEST(RadianceCompat, BsdfFloorSensorsAgreeWithRadiance) {
    test::ScopedRayPath path(kBsdf.c_str());
    Scene scene = sceneIn(kBsdf, "scene.rad");
    auto sensors = readRays(kBsdf, "sensors.txt");
    auto direct = readReference(kBsdf, "reference_ab0.txt");
    expectWithinNoise(scene, sensors, Mode::Sensor, 4, bsdfSettings(0), direct, 0.005);
    auto oneBounce = readReference(kBsdf, "reference_ab1.txt");
    expectWithinNoise(scene, sensors, Mode::Sensor, 16, bsdfSettings(1), oneBounce, 0.02);
}

// test/data/office: a daylit office (gensky sky and sun through two glass windows, six bounces) with desks placed
// by !xform, chairs as instances of a frozen octree and cabinets as a compiled mesh. Radiance's reference is its
// path tracing (-ab 6 -aa 0 -ad 4096 -as 0 -lw 1e-5) averaged over 64 runs: standard error up to 0.24% per
// sensor and 0.39% per ray; README.md there says how it was made and why -as 0. Brume runs the same six
// bounces exactly, 16 × 4096 paths per ray: noise up to about 0.7% (at the back of the room one 4096-path
// estimate varies by 2.7%). Tolerance: each value within 3%
// (four times that), RMS 1% (about twice what the two programs' noise gives; measured: RMS 0.49% for the
// sensors, 0.30% for the rays, at most 1.8%); the issue asks for 2% RMS.
// Each value is the median of 4 means of 4 runs, not the mean of 16: Brume's paths keep the sun seen by way of
// the desks' metal (caustics, which Radiance's ambient rays drop), rare and bright: of 400 runs of the wall
// between the windows (mean 2.259, standard deviation 2.1%) the largest is 1.3 times the mean, and rarer ones
// are larger (one of this test's 16 runs there was about 2.3 times), which moves a mean of 16 by several %.
// What the median leaves out of the mean is below 0.1% there (the 400 runs' mean with and without their
// largest).
TEST(RadianceCompat, DaylitOfficeAgreesWithRadiance) {
    Scene scene = sceneIn(kOffice, "office.rad");
    RenderSettings s = test::fixedSeed();
    s.ambientBounces = 6;
    s.ambientAccuracy = 0;
    s.ambientDivisions = 4096;
    s.minWeight = 1e-5;
    expectAgreement(kOffice, scene, "sensors.txt", 30, Mode::Sensor, "reference_sensors.txt", 0.03, 16, s, 0.01, 4);
    expectAgreement(kOffice, scene, "rays.txt", 9, Mode::View, "reference_rays.txt", 0.03, 16, s, 0.01, 4);
}

namespace {

const std::string kMkillum = std::string(BRUME_TEST_DATA) + "/mkillum/";

// test/data/mkillum's room with its window as `window` (mkillum, twice or glass), and more files.
Scene mkillumRoom(const std::string& window, const std::vector<std::string>& more = {}) {
    test::ScopedRayPath path(kMkillum.c_str());  // illum.dat; illum.cal and skybright.cal are Brume's own
    std::vector<std::string> files{kMkillum + "sky.rad", kMkillum + "room.rad", kMkillum + "window_" + window + ".rad"};
    for (const std::string& f : more) files.push_back(kMkillum + f);
    return loadScene(files);
}

// make_reference.sh's deterministic options there: those of referenceSettings with -av 0 0 0.
RenderSettings mkillumSettings() {
    RenderSettings s = referenceSettings();
    s.ambientValue = Spectrum(0.f);
    return s;
}

}  // namespace

// A window made by Radiance's mkillum (an illum with a brightdata distribution from illum.cal, glass as its
// alternate), a minimal illum whose brightfunc is 2, and plain glass, in a daylit room at -ab 0. The illum's
// pattern is the distribution of the light it sends (next-event estimation of the window); rays that pass it
// (view rays, -i rays, shadow rays to the sun) see its alternate glass with the glass's own modifiers, not
// the pattern, as Radiance's m_light passes them. (Brume once gave the sun patch 2.1 times its light through
// the mkillum window: the pattern multiplied the glass.) Sensors (-I), view rays, -i, and view rays to a glow
// through the window: each within 3% and RMS 1% over all, as the other deterministic comparisons (measured:
// largest 1.7%, at a work-plane point that sees the window edge-on, where Radiance's 64 cells at their
// centres and mkillum's extrapolated data differ most).
TEST(RadianceCompat, MkillumWindowsAgreeWithRadiance) {
    for (const std::string window : {"mkillum", "twice", "glass"}) {
        Scene scene = mkillumRoom(window);
        test::ScopedRayPath path(kMkillum.c_str());
        expectAgreement(kMkillum, scene, "sensors.txt", 32, Mode::Sensor, ("reference_sensors_" + window + ".txt").c_str(),
                        kPerRay, 8, mkillumSettings());
        expectAgreement(kMkillum, scene, "rays.txt", 15, Mode::View, ("reference_rays_" + window + ".txt").c_str(),
                        kPerRay, 8, mkillumSettings());
        expectAgreement(kMkillum, scene, "rays.txt", 15, Mode::IrradianceAtHit,
                        ("reference_irradiance_at_hit_" + window + ".txt").c_str(), kPerRay, 8, mkillumSettings());
        Scene glow = mkillumRoom(window, {"glow.rad"});
        expectAgreement(kMkillum, glow, "rays_glow.txt", 5, Mode::View, ("reference_rays_glow_" + window + ".txt").c_str(),
                        kPerRay, 8, mkillumSettings());
    }
}

// The same room at -ab 1 and -ab 2, path traced by both (-aa 0; Radiance's mean of 64 runs of 4096 paths and
// its standard error, at most 0.7%): the mkillum window lights the room as a source at every bounce. Within
// 4 combined standard errors plus 2% (Radiance's 64 cells at their jittered points, and Brume's own noise:
// 8 estimates of 512 paths; measured RMS 1.1-1.4%). Left out: `outside_facing_window`, which through the window's glass sees the
// sun reflected (8% of it, about half again its light): Brume's paths find that rarely and unbiased, which
// makes its estimate a firefly there, and Radiance drops sources seen through specular paths of ambient rays.
TEST(RadianceCompat, MkillumWindowsLightTheRoomAsRadianceAtEachBounce) {
    std::vector<LabelledRay> sensors;
    for (const LabelledRay& r : readRays(kMkillum, "sensors.txt"))
        if (r.label != "outside_facing_window") sensors.push_back(r);
    ASSERT_EQ(sensors.size(), 31u);
    for (auto [window, bounces] : {std::pair<std::string, int>{"mkillum", 1}, {"mkillum", 2}, {"twice", 1}}) {
        Scene scene = mkillumRoom(window);
        test::ScopedRayPath path(kMkillum.c_str());
        RenderSettings s = mkillumSettings();
        s.ambientBounces = bounces;
        s.ambientAccuracy = 0;
        s.ambientDivisions = 512;
        s.sourceSubdivision = 0.2;  // Brume samples sources exactly at any -ds: fewer shadow rays, same answer
        auto reference = readReference(kMkillum, "reference_sensors_ab" + std::to_string(bounces) + "_" + window + ".txt");
        expectWithinNoise(scene, sensors, Mode::Sensor, 8, s, reference, 0.02);
    }
}
