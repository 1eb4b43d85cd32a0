#include "medium/smoke.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include "medium/testing.h"
#include "ray_path_dir.h"
#include "sampling/random.h"
#include "scene/reader.h"
#include "spectral_sampling_scope.h"
#include "spectrum/colorimetry.h"

namespace brume {
namespace {

using namespace medium::testing;

// The first object of scene text "t.rad" (so errors read "t.rad:1: …").
SceneObject objectOf(const std::string& text) {
    Scene scene;
    std::istringstream in(text);
    readSceneText(scene, in, "t.rad");
    return scene.objects.at(0);
}

SmokeDescription smokeOf(const std::string& text) { return readSmoke(objectOf(text)); }

std::string errorOf(const std::string& text) {
    try {
        smokeOf(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// Voxels 0..14 of 0.1 holding uniform random densities in [0, 3): the majorant grid's 8-voxel cells then
// span exactly the smoke's bounds (index −1 … 15, world −0.1 … 1.5).
openvdb::FloatGrid::Ptr randomGrid(Random& random) {
    auto grid = boxGrid({0, 0, 0}, {14, 14, 14}, 0.0f, 0.1);
    grid->tree().voxelizeActiveTiles();  // a value per voxel, not per 8³ tile
    for (auto it = grid->tree().beginValueOn(); it; ++it) it.setValue(float(3 * random.uniform()));
    return grid;
}

TEST(Smoke, EveryFormReadsItsFilesTimesAndCoefficients) {
    RayPathDir dir;
    writeGrid(dir.path() / "box.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 2.0f, 0.1));
    writeGrid(dir.path() / "soot.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 5.0f, 0.1), "soot");
    // One static grid, no albedo, no g.
    SmokeDescription still = smokeOf("void smoke s 1 box.vdb 0 3 1 2 4");
    ASSERT_EQ(still.frames->keyFrames().size(), 1u);
    EXPECT_EQ(still.frames->density({0.5, 0.5, 0.5}, 1e6), 2.0);
    EXPECT_EQ(still.extinctionPerDensity[0], 1.f);
    EXPECT_EQ(still.extinctionPerDensity[2], 4.f);
    EXPECT_EQ(still.albedo.maxValue(), 0.f);
    EXPECT_EQ(still.g, 0.0);
    // A named grid, albedo and g.
    SmokeDescription named = smokeOf("void smoke s 2 density=soot soot.vdb 0 7 1 1 1 .2 .3 .4 .6");
    EXPECT_EQ(named.frames->density({0.5, 0.5, 0.5}, 0), 5.0);
    EXPECT_FLOAT_EQ(named.albedo[1], 0.3f);
    EXPECT_EQ(named.g, 0.6);
    EXPECT_EQ(smokeOf("void smoke s 1 box.vdb 0 6 1 1 1 .5 .5 .5").g, 0.0);
    // Key frames, in any order.
    SmokeDescription frames = smokeOf("void smoke s 4 20 box.vdb 10 box.vdb 0 3 1 1 1");
    ASSERT_EQ(frames.frames->keyFrames().size(), 2u);
    EXPECT_EQ(frames.frames->keyFrames()[0].time, 10.0);
    EXPECT_EQ(frames.frames->keyFrames()[1].time, 20.0);
    // A name given as a path is taken as given, not searched for.
    EXPECT_EQ(smokeOf("void smoke s 1 " + (dir.path() / "box.vdb").string() + " 0 3 1 1 1").frames->keyFrames().size(),
              1u);
}

TEST(Smoke, GreyExtinctionStaysExactlyFlatInEveryBandCount) {
    RayPathDir dir;
    writeGrid(dir.path() / "box.vdb", boxGrid({0, 0, 0}, {1, 1, 1}, 1.0f));
    for (int bands : {3, 40}) {
        SpectralSamplingScope sampling(bands);
        SmokeDescription soot = smokeOf("void smoke s 1 box.vdb 0 6 8700 8700 8700 .15 .15 .15");
        ASSERT_EQ(soot.extinctionPerDensity.size(), bands);
        for (int i = 0; i < bands; ++i) {
            EXPECT_EQ(soot.extinctionPerDensity[i], 8700.f) << bands << " bands, band " << i;
            EXPECT_EQ(soot.albedo[i], 0.15f) << bands << " bands, band " << i;
        }
    }
}

// Soot's extinction grows toward the blue as λ^−1.39 from its 633 nm value (FDS's K): in 41 bands each band's
// average of the law (1e-4, a 1 nm sum against the closed form ∫λ^−1.39), in RGB the spectrum's colour; the
// photopic mean 1.20 of it in both (0.5 %). A `smoke` with extinction=soot takes its K at 633 nm: its K per band
// is that times soot's spectrum, and the K a study quotes is K itself at 633 nm, about 1.2 K as the eye sees.
TEST(Smoke, SootExtinctionGrowsTowardTheBlueFromItsValueAt633nm) {
    RayPathDir dir;
    writeGrid(dir.path() / "box.vdb", boxGrid({0, 0, 0}, {1, 1, 1}, 1.0f));
    double photopicMean[2];
    for (int bands : {3, 41}) {
        SpectralSamplingScope sampling(bands);
        Spectrum soot = sootExtinction();
        if (bands == 41)
            for (int i = 0; i < bands; ++i) {
                auto b = spectralSampling().band(i);  // longer, shorter
                auto antiderivative = [](double nm) { return std::pow(nm / 633, -0.39) * 633 / -0.39; };
                double mean = (antiderivative(b[0]) - antiderivative(b[1])) / (b[0] - b[1]);
                EXPECT_NEAR(soot[i], mean, 1e-4 * mean) << "band " << i;
            }
        photopicMean[bands == 41] = photopic(soot);
        SmokeDescription d = smokeOf("void smoke s 2 extinction=soot box.vdb 0 3 8700 8700 8700");
        ASSERT_TRUE(d.extinctionAt633);
        EXPECT_EQ(*d.extinctionAt633, 8700);
        for (int i = 0; i < bands; ++i) EXPECT_NEAR(d.extinctionPerDensity[i], 8700 * soot[i], 1e-3 * soot[i]);
        SmokeVolume v(d, 0);
        EXPECT_EQ(v.quotedExtinctionPerDensity(QuotedExtinction::At633nm), 8700);
        EXPECT_NEAR(v.quotedExtinctionPerDensity(QuotedExtinction::Photopic), 8700 * photopic(soot), 1e-5 * 8700);
        SmokeVolume grey(smokeOf("void smoke s 2 extinction=grey box.vdb 0 3 8700 8700 8700"), 0);
        EXPECT_NEAR(grey.quotedExtinctionPerDensity(QuotedExtinction::At633nm), 8700, 1e-5 * 8700);  // (band weights in float)
        EXPECT_NEAR(grey.quotedExtinctionPerDensity(QuotedExtinction::Photopic), 8700, 1e-5 * 8700);
    }
    EXPECT_NEAR(photopicMean[0], 1.20, 0.01);
    EXPECT_NEAR(photopicMean[1], photopicMean[0], 0.005 * photopicMean[0]);
}

TEST(Smoke, EveryMalformedSmokeIsAnErrorAtItsLine) {
    RayPathDir dir;
    writeGrid(dir.path() / "box.vdb", boxGrid({0, 0, 0}, {1, 1, 1}, 1.0f));
    const std::string strings =
        "expected [density=NAME] [temperature=NAME] [extinction=soot] then one file, or key frames as time and file pairs";
    const std::string reals = "expected 3, 6 or 7 reals";
    const std::string noSoot = (dir.path() / "box.vdb").string() + ": no grid \"soot\" (the file holds \"density\")";
    const std::pair<std::string, std::string> cases[] = {  // object's arguments, what is wrong
        {"0 0 3 1 1 1", strings},
        {"1 density=soot 0 3 1 1 1", strings},
        {"3 0 box.vdb 10 0 3 1 1 1", strings},
        {"2 density= box.vdb 0 3 1 1 1", "empty grid name in 'density='"},
        {"2 temperature= box.vdb 0 3 1 1 1", "empty grid name in 'temperature='"},
        {"2 heat=t box.vdb 0 3 1 1 1", "unknown keyword 'heat=t' (density=, temperature=, extinction=)"},
        {"2 extinction=coal box.vdb 0 3 1 1 1", "unknown extinction 'coal' (soot, grey)"},
        {"2 extinction=soot box.vdb 0 3 1 2 1", "extinction=soot takes one K, at 633 nm: the three must be equal"},
        {"4 0 box.vdb soon box.vdb 0 3 1 1 1", "bad key-frame time 'soon'"},
        {"4 0 box.vdb inf box.vdb 0 3 1 1 1", "bad key-frame time 'inf'"},
        {"4 0 box.vdb 5s box.vdb 0 3 1 1 1", "bad key-frame time '5s'"},
        {"4 30 box.vdb 30 box.vdb 0 3 1 1 1", "two key frames at time 30 s"},
        {"1 absent.vdb 0 3 1 1 1", "cannot find VDB file \"absent.vdb\""},
        {"2 density=soot box.vdb 0 3 1 1 1", noSoot},
        {"1 box.vdb 0 0", reals},
        {"1 box.vdb 0 4 1 1 1 .5", reals},
        {"1 box.vdb 0 8 1 1 1 .5 .5 .5 0 0", reals},
        {"1 box.vdb 1 7 3 1 1 1", "expected no integers"},
        {"1 box.vdb 0 3 1 -1 1", "extinction per unit density must not be negative"},
        {"1 box.vdb 0 6 1 1 1 .5 1.5 .5", "albedo must be between 0 and 1"},
        {"1 box.vdb 0 6 1 1 1 .5 -.1 .5", "albedo must be between 0 and 1"},
        {"1 box.vdb 0 7 1 1 1 .5 .5 .5 1", "g must be strictly between -1 and 1"},
        {"1 box.vdb 0 7 1 1 1 .5 .5 .5 -1", "g must be strictly between -1 and 1"},
    };
    for (const auto& [arguments, why] : cases)
        EXPECT_EQ(errorOf("void smoke s " + arguments), "t.rad:1: bad smoke 's': " + why);
    EXPECT_EQ(errorOf("\n\nvoid smoke s 1 absent.vdb 0 3 1 1 1"),
              "t.rad:3: bad smoke 's': cannot find VDB file \"absent.vdb\"");
}

TEST(Smoke, ConstantBoxHasExtinctionKTimesDensityInsideAndNoneOutside) {
    // Voxels 0..9 of 0.1 at density 2: constant between the outer voxel centres 0 … 0.9, zero from one
    // voxel beyond them. Exact: equal voxels interpolate to their value, and 2·K is exact in float.
    RayPathDir dir;
    writeGrid(dir.path() / "box.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 2.0f, 0.1));
    SmokeVolume box(smokeOf("void smoke s 1 box.vdb 0 6 1 2 4 .5 .5 .5"), 0);
    for (const dvec3& p : {dvec3(0.45, 0.45, 0.45), dvec3(0, 0.9, 0.3), dvec3(0.9, 0.9, 0.9)}) {
        const Spectrum sigma = box.extinction(p);
        EXPECT_EQ(sigma[0], 2.f);
        EXPECT_EQ(sigma[1], 4.f);
        EXPECT_EQ(sigma[2], 8.f);
    }
    for (const dvec3& p : {dvec3(1.0, 0.45, 0.45), dvec3(-0.1, 0.45, 0.45), dvec3(0.45, 3, 0.45), dvec3(-7, 1e6, 0)})
        EXPECT_EQ(box.extinction(p).maxValue(), 0.f);
    EXPECT_NEAR(box.bounds().lo.x, -0.1, 1e-12);  // rounding of the voxel size 0.1 only
    EXPECT_NEAR(box.bounds().hi.z, 1.0, 1e-12);
    EXPECT_FLOAT_EQ(box.albedo()[1], 0.5f);
}

TEST(Smoke, MajorantsBoundExtinctionAndSegmentsCoverTheChordOfTheBox) {
    // Two frames of random voxels, seen between them; extinction per band 1, 2, 4, so the largest band
    // sets the majorant. Majorant ≥ extinction is checked exactly: the scale is rounded up for that.
    Random random(7);
    RayPathDir dir;
    writeGrid(dir.path() / "a.vdb", randomGrid(random));
    writeGrid(dir.path() / "b.vdb", randomGrid(random));
    SmokeVolume smoke(smokeOf("void smoke s 4 0 a.vdb 10 b.vdb 0 3 1 2 4"), 3.7);
    const Bounds3 b = smoke.bounds();
    EXPECT_NEAR(b.lo.x, -0.1, 1e-12);
    EXPECT_NEAR(b.hi.x, 1.5, 1e-12);
    int points = 0, inside = 0;
    while (points < 10000) {
        const dvec3 org = dvec3(-1) + 3.5 * dvec3(random.uniform(), random.uniform(), random.uniform());
        const double z = 2 * random.uniform() - 1, phi = 2 * M_PI * random.uniform(), r = std::sqrt(1 - z * z);
        const Ray ray{org, dvec3(r * std::cos(phi), r * std::sin(phi), z)};
        // The ray's chord through the bounds, clipped to [0, 5].
        double near = 0, far = 5;
        for (int a = 0; a < 3; ++a) {
            const double t0 = (b.lo[a] - org[a]) / ray.dir[a], t1 = (b.hi[a] - org[a]) / ray.dir[a];
            near = std::max(near, std::min(t0, t1)), far = std::min(far, std::max(t0, t1));
        }
        std::vector<std::array<double, 4>> segments;
        smoke.forEachBound(ray, 0, 5, [&](double t0, double t1, double most, double least) {
            segments.push_back({t0, t1, most, least});
            return true;
        });
        if (near >= far) {
            EXPECT_TRUE(segments.empty());
            continue;
        }
        ASSERT_FALSE(segments.empty());
        // Cell faces are crossed in cell space, the chord here in world space: 1e-12 allows their rounding.
        EXPECT_NEAR(segments.front()[0], near, 1e-12);
        EXPECT_NEAR(segments.back()[1], far, 1e-12);
        for (std::size_t i = 1; i < segments.size(); ++i) EXPECT_EQ(segments[i][0], segments[i - 1][1]);
        if (near > 0) {  // a point on the ray before it enters the box
            EXPECT_EQ(smoke.density(ray.org + random.uniform() * near * ray.dir), 0.0);
        }
        for (const auto& [t0, t1, m, least] : segments)
            for (int k = 0; k < 10; ++k, ++points) {
                const dvec3 p = ray.org + (t0 + random.uniform() * (t1 - t0)) * ray.dir;
                const double sigma = smoke.extinction(p).maxValue();
                ASSERT_GE(m, sigma) << "segment " << t0 << " … " << t1;
                ASSERT_LE(least, sigma) << "segment " << t0 << " … " << t1;
                inside += sigma > 0;
            }
    }
    EXPECT_GT(inside, 1000);  // the test does meet smoke
}

TEST(Smoke, KeyFramesInterpolateLinearlyInTimeAndRefuseInstantsOutside) {
    // Densities 1 at 10 s and 3 at 20 s: the mean at 15 s, exact since w = 0.5 and the values are small integers.
    RayPathDir dir;
    writeGrid(dir.path() / "thin.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f));
    writeGrid(dir.path() / "thick.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 3.0f));
    const SmokeDescription smoke = smokeOf("void smoke s 4 10 thin.vdb 20 thick.vdb 0 3 2 2 2");
    const dvec3 p(4.5, 4.5, 4.5);
    EXPECT_EQ(SmokeVolume(smoke, 15).density(p), 2.0);
    EXPECT_EQ(SmokeVolume(smoke, 15).extinction(p)[1], 4.f);
    EXPECT_EQ(SmokeVolume(smoke, 12.5).density(p), 1.5);
    EXPECT_EQ(SmokeVolume(smoke, 10).density(p), 1.0);
    EXPECT_EQ(SmokeVolume(smoke, 20).density(p), 3.0);
    // Before the first frame and after the last there is no data: not the nearest frame's smoke.
    for (double outside : {0.0, 9.999, 20.001, 1e9}) {
        try {
            SmokeVolume(smoke, outside);
            ADD_FAILURE() << outside << " s was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("smoke 's': no data at "), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("outside its 2 key frames (10 to 20 s"), std::string::npos) << e.what();
        }
    }
    // The majorant at an instant is that of the frames around it only, weighted as the density is (2·1 at the
    // first frame, 2·(½·1 + ½·3) at 15 s, widened by 2⁻²⁰ for the rounding of the weighted sum).
    const auto majorantAt = [&](double time) {
        double m = 0;
        SmokeVolume(smoke, time).forEachBound(Ray{dvec3(-5, 4.5, 4.5), dvec3(1, 0, 0)}, 0, 100,
                                              [&](double, double, double s, double) { return m = std::max(m, s), true; });
        return m;
    };
    EXPECT_NEAR(majorantAt(10), 2.0, 2 * 0x1p-19);
    EXPECT_NEAR(majorantAt(15), 4.0, 4 * 0x1p-19);
}

// A single grid is static: any instant reads it.
TEST(Smoke, OneGridServesEveryInstant) {
    RayPathDir dir;
    writeGrid(dir.path() / "thin.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f));
    const SmokeDescription smoke = smokeOf("void smoke s 1 thin.vdb 0 3 2 2 2");
    for (double time : {-5.0, 0.0, 1e9}) EXPECT_EQ(SmokeVolume(smoke, time).density(dvec3(4.5)), 1.0) << time;
}

TEST(Smoke, EmptyGridIsAValidSmokeWithNoMedium) {
    RayPathDir dir;
    openvdb::initialize();
    writeGrid(dir.path() / "empty.vdb", openvdb::FloatGrid::create(0.0f));
    SmokeVolume empty(smokeOf("void smoke s 1 empty.vdb 0 3 1 1 1"), 0);
    EXPECT_TRUE(empty.bounds().empty());
    EXPECT_EQ(empty.density({0, 0, 0}), 0.0);
    int segments = 0;
    empty.forEachBound(Ray{dvec3(-5, 0, 0), dvec3(1, 0, 0)}, 0, 1e9, [&](double, double, double, double) {
        ++segments;
        return true;
    });
    EXPECT_EQ(segments, 0);
}

// The FDS frame's time, from its grid metadata "fds_time_s".
double fdsTime(const std::string& path) {
    openvdb::io::File file(path);
    file.open();
    const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
    return std::stod((*grids->at(0))["fds_time_s"]->str());
}

TEST(Smoke, FdsSootFramesAtTheirSimulationTimesGiveTheirExtinction) {
    openvdb::initialize();
    std::string strings;
    std::vector<double> times;
    for (int t = 30; t <= 180; t += 30) {
        char name[64];
        std::snprintf(name, sizeof name, "fds_room_fire_mesh2_soot/soot_t%03d.vdb", t);
        BRUME_SHARED_GRID_OR_SKIP(path, name);
        times.push_back(fdsTime(path));
        EXPECT_NEAR(times.back(), t, 0.02);  // README: 30.004, 60.001, … 180.000 s
        strings += " " + std::to_string(times.back()) + " " + path;
    }
    const SmokeDescription soot = smokeOf("void smoke soot 12" + strings + " 0 6 8700 8700 8700 .15 .15 .15");
    for (const KeyFrame& frame : soot.frames->keyFrames()) {
        // README: maxima 4.6e-5 … 6.0e-5 kg/m³, given to two digits.
        EXPECT_GE(frame.grid.maxDensity(), 4.55e-5);
        EXPECT_LE(frame.grid.maxDensity(), 6.05e-5);
    }
    // Between 90 and 120 s: K = 8700 ρ in every band, bounded by the majorant along rays across the mesh.
    const double time = 0.5 * (times[2] + times[3]);
    SmokeVolume smoke(soot, time);
    Random random(3);
    double largest = 0;
    for (int i = 0; i < 200; ++i) {
        const dvec3 org(10 + 5 * random.uniform(), 5 * random.uniform(), -1);
        const Ray ray{org, glm::normalize(dvec3(random.uniform() - 0.5, random.uniform() - 0.5, 1))};
        smoke.forEachBound(ray, 0, 10, [&](double t0, double t1, double m, double) {
            const dvec3 p = ray.org + (t0 + random.uniform() * (t1 - t0)) * ray.dir;
            const Spectrum sigma = smoke.extinction(p);
            EXPECT_EQ(sigma[0], sigma[2]);
            EXPECT_NEAR(sigma[1], 8700 * smoke.density(p), 1e-6 * sigma[1]);  // float rounding
            EXPECT_GE(m, sigma[1]);
            largest = std::max(largest, m);
            return true;
        });
    }
    EXPECT_GT(largest, 0.3);  // K ≈ 0.40 … 0.53 1/m at the frames' maxima
    EXPECT_LT(largest, 8700 * 6.05e-5);
}

}  // namespace
}  // namespace brume
