// Models at their site coordinates (UTM: x ~ 5e5, y ~ 5e6 m), at any scale, and beside objects far larger or
// farther than themselves, give the answers they give at the origin: the analytic cases at offsets 0, 1e3,
// 5e6 and 1e7 m and scales 1e-3 … 1e3, a ground 2000 km wide, a ball 1e12 m away, millimetre details, and
// the example office at a UTM position against a converged reference.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "render/picture_renderer.h"
#include "render/shared_bounces.h"
#include "scene/reader.h"
#include "closed_forms.h"
#include "scene_text.h"

using namespace brume;
using namespace brume::test;
using std::numbers::pi;

namespace {

// A model's coordinates scaled by k about the origin, then moved to `offset`; written with every digit.
struct Site {
    dvec3 offset{0};
    double k = 1;
    dvec3 at(const dvec3& p) const { return offset + k * p; }
    std::string point(const dvec3& p) const {
        dvec3 q = at(p);
        char s[96];
        std::snprintf(s, sizeof s, " %.17g %.17g %.17g", q.x, q.y, q.z);
        return s;
    }
    std::string length(double l) const {
        char s[32];
        std::snprintf(s, sizeof s, " %.17g", k * l);
        return s;
    }
    std::string label() const {
        char s[96];
        std::snprintf(s, sizeof s, "offset (%g, %g, %g), scale %g", offset.x, offset.y, offset.z, k);
        return s;
    }
};

const dvec3 kUtm(512345.6, 5412345.7, 120);

std::vector<Site> sites() {
    std::vector<Site> out;
    for (dvec3 o : {dvec3(0), dvec3(1e3, -1e3, 1e3), kUtm, dvec3(5e6, 5e6, 5e6), dvec3(1e7, -1e7, 1e7)})
        for (double k : {1e-3, 1.0, 1e3}) out.push_back({o, k});
    return out;
}

// Radiance's polygon of four corners.
std::string quad(const Site& s, const std::string& head, dvec3 a, dvec3 b, dvec3 c, dvec3 d) {
    return head + " 0 0 12" + s.point(a) + s.point(b) + s.point(c) + s.point(d) + "\n";
}

// A sphere lamp of radius .1 at height 2 over a grey ground polygon `half` wide each way (in model units).
std::string lampOverGround(const Site& s, double half = 10) {
    return "void light lum 0 0 3 100 100 100\nlum sphere bulb 0 0 4" + s.point({0, 0, 2}) + s.length(0.1) +
           "\nvoid plastic grey 0 0 5 .5 .5 .5 0 0\n" +
           quad(s, "grey polygon ground", {-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0});
}

// The lamp's irradiance at p (model units) on a sensor facing n.
double lampIrradiance(const dvec3& p, const dvec3& n) { return sphereIrradiance(100, 0.1, {0, 0, 2}, p, n); }

// Sensors in model units: on the ground, 1 mm (of the model) above it, tilted, and in mid-air.
const std::pair<dvec3, dvec3> kSensors[] = {{{0, 0, 0}, {0, 0, 1}},           {{1, 0, 0}, {0, 0, 1}},
                                            {{0.5, -1.5, 1e-3}, {0, 0, 1}},   {{-0.7, 0.2, 1e-3}, {0.3, 0, 1}},
                                            {{0.5, -1.5, 0.3}, {-0.2, 0.4, 1}}};

}  // namespace

// Tolerance 0.5% against the closed form, as Analytic.SphereSourceOnPlaneGivesPiLSquaredRatioForAnyTilt
// (the cone's cos β spread, averaged by 64 stratified samples); against the origin's own value 5e-4: the
// same samples, the sensor lifted off its surface by double rounding (1e-14 of its coordinates: 1e-4 of
// the lamp's distance at scale 1e-3 and 1e7 m).
TEST(SiteCoordinates, SphereSourceOverGroundGivesTheSameAnywhereAtAnyScale) {
    RenderSettings settings = fixedSeed();
    settings.sourceSubdivision = 0.01;
    std::map<double, std::vector<double>> atOrigin;  // per scale
    for (const Site& site : sites()) {
        TestScene t(lampOverGround(site));
        Integrator integrator(t.render, settings);
        std::vector<double>& origin = atOrigin[site.k];
        for (size_t i = 0; i < std::size(kSensors); ++i) {
            const auto& [p, n] = kSensors[i];
            double value = meanIrradiance(integrator, site.at(p), n, 4);
            double expected = lampIrradiance(p, n);
            EXPECT_NEAR(value, expected, 0.005 * expected) << site.label() << ", sensor " << i;
            if (site.offset == dvec3(0)) origin.push_back(value);
            EXPECT_NEAR(value, origin[i], 5e-4 * origin[i]) << site.label() << ", sensor " << i;
        }
    }
}

// Tolerance 1%, as Analytic.RectangleSourceMatchesCornerFormFactor: 32 estimates of 64 stratified samples.
TEST(SiteCoordinates, RectangleSourceMatchesItsFormFactorAnywhereAtAnyScale) {
    RenderSettings settings = fixedSeed();
    settings.sourceSubdivision = 0.01;
    for (const Site& site : sites()) {
        TestScene t("void light panel 0 0 3 50 50 50\n" +
                    quad(site, "panel polygon ceiling", {0, 0, 2}, {0, 3, 2}, {2, 3, 2}, {2, 0, 2}) +
                    "void plastic grey 0 0 5 .5 .5 .5 0 0\n" +
                    quad(site, "grey polygon floor", {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}));
        Integrator integrator(t.render, settings);
        double corner = pi * 50 * cornerFormFactor(2, 3, 2), middle = 4 * pi * 50 * cornerFormFactor(1, 1.5, 2);
        EXPECT_NEAR(meanIrradiance(integrator, site.at({0, 0, 0}), {0, 0, 1}, 32), corner, 0.01 * corner)
            << site.label();
        EXPECT_NEAR(meanIrradiance(integrator, site.at({1, 1.5, 1e-3}), {0, 0, 1}, 32), middle, 0.01 * middle)
            << site.label();
        EXPECT_EQ(meanIrradiance(integrator, site.at({1, 1, 3}), {0, 0, -1}, 4), 0.0) << site.label();
    }
}

namespace {

// Inside a closed sphere of reflectance ρ lit by a small central lamp of flux Φ, every wall point receives
// E₀ = Φ/(4πR²) directly, and each interreflection multiplies the previous uniform irradiance by ρ.
struct IntegratingSphere {
    Site site;
    double rho = 0.5, lampRadius = 0.02, lampRadiance = 1000;
    std::string text() const {
        return "void plastic wall 0 0 5 .5 .5 .5 0 0\nwall bubble inside 0 0 4" + site.point({0, 0, 0}) +
               site.length(1) + "\nvoid light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4" +
               site.point({0, 0, 0}) + site.length(lampRadius) + "\n";
    }
    double afterBounces(int n) const {
        double direct = lampRadius * lampRadius * pi * lampRadiance;  // Φ/(4πR²), R = 1
        return direct * (1 - std::pow(rho, n + 1)) / (1 - rho);
    }
    // Mean irradiance over sensors on the wall, facing the centre.
    double measure(const RenderSettings& s) const {
        TestScene t(text());
        Sequence sequence(t.scene, t.render, s);
        const dvec3 dirs[] = {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-0.6, 0.8, 0}, {0, -0.6, 0.8}, {0.48, 0.6, -0.64}};
        std::vector<double> values(std::size(dirs));
        sequence.run(values.size(), 0, [&](size_t i, WorkItem& item) {
            values[i] = sequence.integrator().irradiance({site.at(dirs[i]), -dirs[i], uint64_t(i)}, item).value[0];
        });
        double sum = 0;
        for (double v : values) sum += v;
        return sum / values.size();
    }
};

}  // namespace

// Sensors exactly on the sphere's wall, path traced (-ab 2 -aa 0) and through the irradiance cache (all
// bounces). Tolerance 1.5%, as Analytic.IntegratingSphereMatchesAnalyticAtEachBounceCount (6 sensors ×
// 2048 paths: ~0.3% noise; the cache: -aa .1 of the indirect light, averaged over six sensors).
TEST(SiteCoordinates, IntegratingSphereMatchesAnalyticAnywhereAtAnyScale) {
    for (dvec3 offset : {dvec3(0), kUtm, dvec3(1e7, -1e7, 1e7)}) {
        for (double k : {1e-3, 1.0, 1e3}) {
            IntegratingSphere sphere{{offset, k}};
            RenderSettings s = fixedSeed();
            s.ambientAccuracy = 0, s.ambientDivisions = 2048, s.ambientBounces = 2;
            EXPECT_NEAR(sphere.measure(s), sphere.afterBounces(2), 0.015 * sphere.afterBounces(2))
                << sphere.site.label();
            RenderSettings cached = fixedSeed();
            cached.ambientBounces = 5;
            double all = sphere.afterBounces(1000);
            EXPECT_NEAR(sphere.measure(cached), all, 0.015 * all) << "cache, " << sphere.site.label();
        }
    }
}

// A ground 2000 km and one 2×10⁹ m wide, and a 1 cm ball 10¹² m away, change nothing they do not block:
// the lamp's sensors get what they get over a 20 m ground, at the origin and at a UTM position, and the
// scene's scale (how far sensors lift off surfaces, the cache's record radii) stays the model's.
// Tolerances as SphereSourceOverGroundGivesTheSameAnywhereAtAnyScale.
TEST(SiteCoordinates, HugeAndFarObjectsChangeNothingTheyDoNotBlock) {
    RenderSettings settings = fixedSeed();
    settings.sourceSubdivision = 0.01;
    for (dvec3 offset : {dvec3(0), kUtm}) {
        Site site{offset};
        const std::string far = "grey sphere far 0 0 4" + site.point({1e12, 0, 0}) + " 0.01\n";
        const std::string lamp = lampOverGround(site).substr(0, lampOverGround(site).find("void plastic"));
        // Each scene, and the one without its huge or far objects, whose scale it must keep.
        const std::pair<std::string, std::string> scenes[] = {{lampOverGround(site, 1e6), lamp},
                                                              {lampOverGround(site, 1e9), lamp},
                                                              {lampOverGround(site) + far, lampOverGround(site)},
                                                              {lampOverGround(site, 1e6) + far, lamp}};
        for (const auto& [text, without] : scenes) {
            TestScene t(text), baseline(without);
            Integrator integrator(t.render, settings);
            for (size_t i = 0; i < std::size(kSensors); ++i) {
                const auto& [p, n] = kSensors[i];
                double expected = lampIrradiance(p, n);
                EXPECT_NEAR(meanIrradiance(integrator, site.at(p), n, 4), expected, 0.005 * expected)
                    << site.label() << ", sensor " << i << " in\n" << text;
            }
            RecordShape shape = recordShape(t.render, settings), expected = recordShape(baseline.render, settings);
            EXPECT_EQ(shape.maxRadius, expected.maxRadius) << text;
            EXPECT_EQ(shape.minRadius, expected.minRadius) << text;
        }
    }
}

// At a UTM position and beside a ground 2000 km wide, millimetre details still shadow: a 2 mm square and a
// 2 mm ball 1 cm above sensors hide the lamp (r/d = .05, narrower than the 0.1 rad they subtend), sensors
// 5 mm aside see it whole, and sensors in their penumbra get what they get at the origin (the same samples:
// 1e-3).
TEST(SiteCoordinates, MillimetreDetailsShadowAtSiteCoordinates) {
    RenderSettings settings = fixedSeed();
    settings.sourceSubdivision = 0.01;
    std::vector<double> origin;
    for (dvec3 offset : {dvec3(0), kUtm, dvec3(1e7, -1e7, 1e7)}) {
        Site site{offset};
        TestScene t(lampOverGround(site, 1e6) + "void plastic black 0 0 5 0 0 0 0 0\n" +
                    quad(site, "black polygon chip", {-1e-3, -1e-3, 0.01}, {1e-3, -1e-3, 0.01}, {1e-3, 1e-3, 0.01},
                         {-1e-3, 1e-3, 0.01}) +
                    "black sphere bead 0 0 4" + site.point({0.4975, 0, 0.01}) + " 1e-3\n");
        Integrator integrator(t.render, settings);
        std::vector<double> penumbra;
        for (double x : {0.0, 0.5}) {
            EXPECT_EQ(meanIrradiance(integrator, site.at({x, 0, 0}), {0, 0, 1}, 4), 0.0) << site.label() << " x " << x;
            double whole = lampIrradiance({x + 5e-3, 0, 0}, {0, 0, 1});
            EXPECT_NEAR(meanIrradiance(integrator, site.at({x + 5e-3, 0, 0}), {0, 0, 1}, 4), whole, 0.005 * whole)
                << site.label() << " x " << x;
            for (double dx : {1e-3, 1.5e-3, 2e-3})
                penumbra.push_back(meanIrradiance(integrator, site.at({x + dx, 0, 1e-3}), {0, 0, 1}, 4));
        }
        if (offset == dvec3(0)) origin = penumbra;
        for (size_t i = 0; i < penumbra.size(); ++i) {
            EXPECT_GT(origin[i], 0);
            EXPECT_NEAR(penumbra[i], origin[i], 1e-3 * lampIrradiance({0, 0, 0}, {0, 0, 1})) << site.label() << " " << i;
        }
    }
}

namespace {

std::vector<std::pair<dvec3, dvec3>> labelledRays(const std::string& file) {
    std::vector<std::pair<dvec3, dvec3>> rays;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        std::string label;
        dvec3 o, d;
        f >> label >> o.x >> o.y >> o.z >> d.x >> d.y >> d.z;
        rays.push_back({o, d});
    }
    return rays;
}

// The values of a scene's view rays (also with -i), sensors (-I) and a picture at -ab `bounces` -aa 0, with
// the scene, rays and view moved by `offset`.
std::vector<double> valuesAt(const dvec3& offset, const std::string& dir, const std::string& file, View view,
                             int bounces) {
    const std::vector<std::pair<dvec3, dvec3>> rays = labelledRays(dir + "rays.txt"),
                                               sensors = labelledRays(dir + "sensors.txt");
    char xform[128];
    std::snprintf(xform, sizeof xform, "!xform -t %.17g %.17g %.17g ", offset.x, offset.y, offset.z);
    TestScene t(xform + dir + file + "\n");
    view.vp += offset;
    RenderSettings s = fixedSeed();
    s.ambientBounces = bounces;
    s.ambientAccuracy = 0;  // the cache at a site: CachedIrradiance.OfficeSensorsStayWithin…
    s.ambientDivisions = 64;
    Sequence sequence(t.scene, t.render, s);
    const Integrator& integrator = sequence.integrator();
    const size_t n = rays.size();
    std::vector<double> values(2 * n + sensors.size());
    sequence.run(values.size(), 0, [&](size_t i, WorkItem& item) {
        if (i < n)
            values[i] = brightness(integrator.trace({rays[i].first + offset, rays[i].second, i}, item).value);
        else if (i < 2 * n)
            values[i] = brightness(integrator.irradianceAtHit({rays[i - n].first + offset, rays[i - n].second, i}, item).value);
        else
            values[i] = brightness(integrator.irradiance({sensors[i - 2 * n].first + offset, sensors[i - 2 * n].second, i}, item).value);
    });
    PictureSettings ps;
    ps.xres = 40, ps.yres = 30;
    fitResolution(view, ps);
    const std::vector<float>& pixels = renderPicture(sequence, view, 0, ps).picture.pixels;
    for (size_t p = 0; p < pixels.size(); p += 3) values.push_back(pixels[p] + pixels[p + 1] + pixels[p + 2]);
    return values;
}

// The office's sensors (-I) at -ab 3 with shared bounces (rtrace's defaults: lib/render/shared_bounces), the scene
// and the sensors moved by `offset`.
std::vector<double> sharedSensorsAt(const dvec3& offset, const std::string& dir) {
    const std::vector<std::pair<dvec3, dvec3>> sensors = labelledRays(dir + "sensors.txt");
    char xform[128];
    std::snprintf(xform, sizeof xform, "!xform -t %.17g %.17g %.17g ", offset.x, offset.y, offset.z);
    TestScene t(xform + dir + "office.rad\n");
    RenderSettings s = fixedSeed();
    s.ambientBounces = 3;
    s.ambientDivisions = 256;
    Sequence sequence(t.scene, t.render, s);
    const Integrator& integrator = sequence.integrator();
    SharedBounces shared(kShareBouncesDefault, continuationsPerCell(s.ambientDivisions), 3, 3,
                         t.render.geometry().origin());
    shared.reset(sensors.size());
    std::vector<RayRecord> records(sensors.size());
    sequence.runPaths(sensors.size(), 0, [&](size_t i, WorkItem& item) {
        WorkItem sharing{item.scratch, nullptr, nullptr, &shared.of(i)};
        records[i] = integrator.irradiance({sensors[i].first + offset, sensors[i].second, i}, sharing);
    });
    shared.resolveValues(sequence, integrator, 0, 0, records);
    std::vector<double> values;
    for (const RayRecord& r : records) values.push_back(brightness(r.value));
    return values;
}

}  // namespace

// Shared bounces count their cells' cubes from the scene's origin, their faces off the round distances walls lie
// at: at its site's coordinates the office's sensors fall in the cells they fall in at (0, 0, 0) and take the same
// paths, each sensor's value the origin's to 1e-4 (1.6e-7 measured; with the cubes' faces on the walls, hits there
// tipped from cube to cube by rounding and 17 of the 30 sensors moved by 0.5 to 4 %).
TEST(SiteCoordinates, SharedBouncesGiveTheOriginsValuesAtTheSite) {
    const std::string dir = std::string(BRUME_TEST_DATA) + "/office/";
    ScopedRayPath path(dir.c_str());
    std::vector<double> origin = sharedSensorsAt(dvec3(0), dir), site = sharedSensorsAt(kUtm, dir);
    ASSERT_EQ(site.size(), 30u);
    for (size_t i = 0; i < site.size(); ++i) EXPECT_NEAR(site[i], origin[i], 1e-4 * origin[i]) << "sensor " << i;
}

// A scene moved to its site's UTM coordinates gives the origin's values: the daylit office of
// test/data/office (gensky's sun and sky through glass, desks placed by !xform, chairs by instances of an
// octree, cabinets by meshes), and the room of test/data/radiance with every surface, material and emitter
// type. The same samples are drawn, and every length measured from the scene's own origin is the same, so at
// -ab 0 every value is the origin's to 1e-6 (sensors lift off their surfaces by 1e-14 of their
// coordinates). At -ab 2 a path may part from its twin where rounding of the order of the coordinates'
// ulp (1e-9 m there) tips a choice (a sample grazing an edge): at most 2% of the values differ by more, and
// their mean stays within 1% (the noise of 64 paths).
TEST(SiteCoordinates, ScenesAtTheirSiteGiveTheOriginsValues) {
    struct Case {
        std::string dir, file;
        dvec3 vp, vd;
        size_t rays, sensors;
    };
    for (const Case& c : {Case{"office/", "office.rad", {5.5, 3.5, 1.6}, {-1, -0.8, -0.3}, 9, 30},
                          Case{"radiance/", "materials.rad", {5.5, 4.5, 2.5}, {-1, -0.8, -0.5}, 99, 70}}) {
        const std::string dir = std::string(BRUME_TEST_DATA) + "/" + c.dir;
        ScopedRayPath path(dir.c_str());
        ASSERT_EQ(labelledRays(dir + "rays.txt").size(), c.rays);
        ASSERT_EQ(labelledRays(dir + "sensors.txt").size(), c.sensors);
        View view;
        view.vp = c.vp, view.vd = c.vd, view.vh = 75, view.vv = 55;
        for (int bounces : {0, 2}) {
            std::vector<double> origin = valuesAt(dvec3(0), dir, c.file, view, bounces),
                                site = valuesAt(kUtm, dir, c.file, view, bounces);
            ASSERT_EQ(site.size(), origin.size());
            size_t apart = 0;
            double sumOrigin = 0, sumSite = 0;
            for (size_t i = 0; i < site.size(); ++i) {
                bool same = std::abs(site[i] - origin[i]) <= 1e-6 * origin[i] + 1e-9;
                if (bounces == 0) {
                    EXPECT_TRUE(same) << c.file << " " << i << ": " << site[i] << " " << origin[i];
                }
                apart += !same;
                sumOrigin += origin[i], sumSite += site[i];
            }
            EXPECT_LE(apart, site.size() / 50) << c.file << " -ab " << bounces;
            EXPECT_NEAR(sumSite, sumOrigin, 0.01 * sumOrigin) << c.file << " -ab " << bounces;
        }
    }
}
