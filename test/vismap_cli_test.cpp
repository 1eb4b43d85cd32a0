// vismap end to end: what it measures along sight lines against closed forms and a numerical single-scattering
// integral, Jin's column against S = C/K, its maps, and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "cli.h"
#include "io/picture.h"
#include "medium/testing.h"
#include "scene_text.h"
#include "scratch_dir.h"
#include "visibility/sign.h"

namespace {

using brume::dvec3;
using brume_test::Output;

// A glowing sign 0.3 m x 0.3 m (100 in Radiance units: 17,900 cd/m²) facing +x at x = 0, 1 cm before a glowing
// wall of a tenth of its luminance.
const char* const kSignScene =
    "void glow sign_glow 0 0 4 100 100 100 0\n"
    "void glow wall_glow 0 0 4 10 10 10 0\n"
    "sign_glow polygon sign 0 0 12  0 -0.15 1.6  0 0.15 1.6  0 0.15 1.9  0 -0.15 1.9\n"
    "wall_glow polygon wall 0 0 12  -0.01 -5 0  -0.01 5 0  -0.01 5 5  -0.01 -5 5\n";
constexpr double kLuminance = 179;  // cd/m² per Radiance unit of white

// One CSV row: column name → text.
using Row = std::map<std::string, std::string>;

std::vector<Row> csv(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    std::stringstream head(line);
    for (std::string w; std::getline(head, w, ',');) names.push_back(w);
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::stringstream cells(line);
        Row row;
        for (const std::string& name : names) std::getline(cells, row[name], ',');
        rows.push_back(row);
    }
    return rows;
}

double number(const Row& row, const std::string& name) { return std::stod(row.at(name)); }

class Vismap : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = brume_test::scratchDir("vismap");
        std::ofstream(dir_ / "signs.txt") << "sign emitting\n";
        std::ofstream(dir_ / "sign.rad") << kSignScene;
    }
    Output run(const std::string& line) { return brume_test::runBrume(line, dir_); }
    void waypoints(const std::string& text) { std::ofstream(dir_ / "route.txt") << text; }
    brume::Sign sign() {
        brume::Scene scene = brume::test::sceneFromText(kSignScene);
        return brume::signFromScene(scene, "sign", brume::SignKind::Emitting, 8);
    }
    std::filesystem::path dir_;
};

// The mean over the aim points of the luminance a ray to each brings: `along(eye, target, length)` of the ray to
// the surface `length` away. Band points lie on the sign's plane; their rays go on to the wall 1 cm behind it.
template <typename Along>
double meanOver(const std::vector<dvec3>& points, const dvec3& eye, bool wall, Along along) {
    double sum = 0;
    for (const dvec3& p : points) {
        double length = glm::length(p - eye) * (wall ? (eye.x + 0.01) / eye.x : 1.0);
        sum += along(eye, p, length);
    }
    return sum / double(points.size());
}

// Absorbing smoke (albedo 0) dims the sign and its background by the same e^{-Kd}: their contrast is the
// clear air's (the band's rays, longer, change it by 0.6 % at 2 m), each luminance that of the closed form at
// every aim point (1e-4: printed digits), and Jin's S = C/K exactly, for the global medium and for smoke.
TEST_F(Vismap, AbsorbingSmokeDimsSignAndBackgroundAlike) {
    waypoints("a 2 0 1.75\nb 5 0 1.75\nc 10 0 1.75\n");
    {
        namespace mt = brume::medium::testing;
        // Density 1 over x -2…12, y -6…6, z -1…6 (voxels of 0.5 m): K = 0.3 /m from the object's extinction.
        mt::writeGrid(dir_ / "box.vdb", mt::boxGrid({-4, -12, -2}, {24, 12, 12}, 1.0f, 0.5));
        std::ofstream(dir_ / "smoke.rad") << "void smoke box 1 box.vdb 0 7 .3 .3 .3 0 0 0 0\n";
    }
    const double k = 0.3;
    brume::Sign s = sign();
    std::vector<dvec3> on = brume::pointsOnSign(s, 32), around = brume::pointsAroundSign(s, 32);
    for (const std::string& medium : {std::string("-me .3 .3 .3 -ma 0 0 0 sign.rad"), std::string("sign.rad smoke.rad")}) {
        SCOPED_TRACE(medium);
        Output r = run("vismap -S signs.txt -wp route.txt -ab 0 " + medium);
        ASSERT_EQ(r.status, 0) << r.err;
        std::vector<Row> rows = csv(r.out);
        ASSERT_EQ(rows.size(), 3u);
        for (const Row& row : rows) {
            dvec3 eye(number(row, "x"), 0, 1.75);
            auto dimmed = [&](double l0) {
                return [=](const dvec3&, const dvec3&, double length) { return l0 * kLuminance * std::exp(-k * length); };
            };
            double signL = meanOver(on, eye, false, dimmed(100)), wallL = meanOver(around, eye, true, dimmed(10));
            EXPECT_NEAR(number(row, "sign_cd_m2"), signL, 1e-4 * signL) << row.at("observer");
            EXPECT_NEAR(number(row, "background_cd_m2"), wallL, 1e-4 * wallL) << row.at("observer");
            // The clear air's 9 but for the band's rays being longer than the sign's (by 1 cm and their slant):
            // 0.6 % at 2 m.
            EXPECT_NEAR(number(row, "contrast"), signL / wallL - 1, 1e-3 * 9);
            EXPECT_NEAR(number(row, "contrast"), 9, 0.01 * 9);
            EXPECT_NEAR(number(row, "optical_depth"), k * eye.x, 1e-3 * k * eye.x);
            EXPECT_NEAR(number(row, "jin_distance_m"), 8 / k, 1e-3 * 8 / k);
            EXPECT_EQ(row.at("jin_verdict"), 8 / k >= eye.x ? "visible" : "not-visible");
            EXPECT_EQ(row.at("verdict"), "visible");
            EXPECT_EQ(number(row, "seen_share"), 1);
        }
    }
    // Jin's verdict turns where C = K d: at 8 / 0.3 = 26.7 m.
    waypoints("near 26 0 1.75\nfar 27.5 0 1.75\n");
    std::vector<Row> rows = csv(run("vismap -S signs.txt -wp route.txt -ab 0 -me .3 .3 .3 -ma 0 0 0 sign.rad").out);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].at("jin_verdict"), "visible");
    EXPECT_EQ(rows[1].at("jin_verdict"), "not-visible");
}

// Soot (extinction=soot, K given at 633 nm) dims the sign by its spectrum, more in the blue: Jin's law and the
// optical depth quote K at 633 nm by default, FDS's and FDSVisMap's, the same in RGB and in 41 bands (printed
// digits), and with -vk photopic the eye's mean K, 1.20 times it (1 % in both); the CSV says which.
TEST_F(Vismap, JinsLawQuotesSootsKAt633nmInRgbAndSpectralRuns) {
    waypoints("a 5 0 1.75\n");
    {
        namespace mt = brume::medium::testing;
        mt::writeGrid(dir_ / "box.vdb", mt::boxGrid({-4, -12, -2}, {24, 12, 12}, 1.0f, 0.5));
        std::ofstream(dir_ / "soot.rad") << "void smoke box 2 extinction=soot box.vdb 0 3 .3 .3 .3\n";
    }
    for (const std::string& bands : {std::string(""), std::string("-cs 41 ")}) {
        SCOPED_TRACE(bands);
        for (const std::string& quoted : {std::string(""), std::string("-vk 633 "), std::string("-vk photopic ")}) {
            Output r = run("vismap -S signs.txt -wp route.txt -ab 0 " + bands + quoted + "sign.rad soot.rad");
            ASSERT_EQ(r.status, 0) << r.err;
            std::vector<Row> rows = csv(r.out);
            ASSERT_EQ(rows.size(), 1u);
            bool photopic = quoted.find("photopic") != std::string::npos;
            EXPECT_EQ(rows[0].at("extinction_quoted"), photopic ? "photopic" : "633nm");
            double k = photopic ? 0.3 * 1.20 : 0.3;
            EXPECT_NEAR(number(rows[0], "mean_extinction_1_m"), k, (photopic ? 0.01 : 1e-3) * k) << quoted;
            EXPECT_NEAR(number(rows[0], "optical_depth"), 5 * k, (photopic ? 0.01 : 1e-3) * 5 * k) << quoted;
        }
    }
    EXPECT_NE(run("vismap -S signs.txt -wp route.txt -vk 550 sign.rad soot.rad").status, 0);
}

// Smoke that scatters, lit from the side by a small lamp, veils the sign and its background alike with the light
// it scatters toward the eye: their contrast falls. At -ab 0 that is single scattering, here against a numerical
// integral along each sight line (Simpson, 2000 steps: far below the test's tolerance) of
// e^{-σt s} σs/(4π) E(s), E the lamp's irradiance π L r² / R² e^{-σt R} (exact for a sphere, R to its centre;
// its 1 cm radius changes the path by 0.3 %). One run's standard deviation, over 12 runs: 0.06 % for the sign,
// 0.31 % for the background (whose light is 40 % veil); the tolerances, 1 % and 1.5 %, are about five of them.
TEST_F(Vismap, ScatteringSmokeLitFromTheSideVeilsTheSign) {
    waypoints("b 5 0 1.75\n");
    std::ofstream(dir_ / "lamp.rad") << "void light lamp_light 0 0 3 1e6 1e6 1e6\nlamp_light sphere lamp 0 0 4  2.5 1.5 1.75 0.01\n";
    Output r = run("vismap -S signs.txt -wp route.txt -ab 0 -vr 1024 -me .3 .3 .3 -ma .5 .5 .5 sign.rad lamp.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<Row> rows = csv(r.out);
    ASSERT_EQ(rows.size(), 1u);
    const double sigmaT = 0.3, sigmaS = 0.15, lamp = 1e6, radius = 0.01;
    const dvec3 lampAt(2.5, 1.5, 1.75);
    auto seen = [&](double l0) {
        return [=](const dvec3& eye, const dvec3& target, double length) {
            const dvec3 dir = glm::normalize(target - eye);
            const int n = 2000;
            double h = length / n, veil = 0;
            for (int i = 0; i <= n; ++i) {
                dvec3 p = eye + (i * h) * dir;
                double R = glm::length(lampAt - p);
                double f = std::exp(-sigmaT * i * h) * sigmaS / (4 * M_PI) * lamp * M_PI * radius * radius / (R * R) *
                           std::exp(-sigmaT * R);
                veil += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * f;
            }
            return kLuminance * (l0 * std::exp(-sigmaT * length) + veil * h / 3);
        };
    };
    brume::Sign s = sign();
    const dvec3 eye(5, 0, 1.75);
    double signL = meanOver(brume::pointsOnSign(s, 1024), eye, false, seen(100));
    double wallL = meanOver(brume::pointsAroundSign(s, 1024), eye, true, seen(10));
    EXPECT_NEAR(number(rows[0], "sign_cd_m2"), signL, 0.01 * signL);
    EXPECT_NEAR(number(rows[0], "background_cd_m2"), wallL, 0.015 * wallL);
    double contrast = (signL - wallL) / wallL;
    EXPECT_LT(contrast, 6);  // 9 without the veil
    EXPECT_NEAR(number(rows[0], "contrast"), contrast, 0.03 * contrast);
}

// A model at its site's coordinates (UTM) gives the numbers it gives at the origin.
TEST_F(Vismap, SiteCoordinatesChangeNothing) {
    waypoints("a 2 0 1.75\nb 5 0.5 1.75\n");
    std::ofstream(dir_ / "far_route.txt") << "a 500002 5000000 1.75\nb 500005 5000000.5 1.75\n";
    const std::string options = "-S signs.txt -ab 0 -me .3 .3 .3 -ma 0 0 0 ";
    std::vector<Row> here = csv(run("vismap " + options + "-wp route.txt sign.rad").out);
    std::vector<Row> there =
        csv(run("vismap " + options + "-wp far_route.txt '!xform -t 500000 5000000 0 sign.rad'").out);
    ASSERT_EQ(here.size(), 2u);
    ASSERT_EQ(there.size(), 2u);
    for (size_t i = 0; i < 2; ++i)
        for (const char* column : {"distance_m", "sign_cd_m2", "background_cd_m2", "contrast", "visibility_level",
                                   "optical_depth", "jin_distance_m"})
            EXPECT_NEAR(number(there[i], column), number(here[i], column), 1e-4 * std::abs(number(here[i], column)))
                << column << " " << here[i].at("observer");
    EXPECT_EQ(there[1].at("x"), "500005");
}

// -u- gives the same answer on any number of threads (the caches' records made in an order of their own).
TEST_F(Vismap, SameAnswerOnAnyNumberOfThreads) {
    waypoints("a 3 1 1.75\nb 6 -1 1.75\n");
    std::ofstream(dir_ / "lamp.rad") << "void light lamp_light 0 0 3 1e4 1e4 1e4\nlamp_light sphere lamp 0 0 4  2.5 1.5 1.75 0.05\n"
                                        "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon floor 0 0 12  -1 -5 0  9 -5 0  9 5 0  -1 5 0\n";
    const std::string line = "vismap -S signs.txt -wp route.txt -u- -ab 1 -ad 64 -me .2 .2 .2 -ma .5 .5 .5 ";
    Output one = run(line + "-n 1 sign.rad lamp.rad"), two = run(line + "-n 2 sign.rad lamp.rad");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(one.out, two.out);
    EXPECT_EQ(std::count(one.out.begin(), one.out.end(), '\n'), 3);
}

// The visibility level's standard error comes from the rays' spread; a sight line whose level lies within two of
// them of the criterion takes another pass of rays (-vp), which brings it down by about √2.
TEST_F(Vismap, SightLinesNearTheCriterionTakeMoreRays) {
    waypoints("b 5 0 1.75\n");
    std::ofstream(dir_ / "lamp.rad") << "void light lamp_light 0 0 3 1e6 1e6 1e6\nlamp_light sphere lamp 0 0 4  2.5 1.5 1.75 0.01\n";
    const std::string line = "vismap -S signs.txt -wp route.txt -u- -ab 0 -vr 64 -me .3 .3 .3 -ma .5 .5 .5 ";
    std::vector<Row> first = csv(run(line + "-vp 1 sign.rad lamp.rad").out);
    ASSERT_EQ(first.size(), 1u);
    double level = number(first[0], "visibility_level"), error = number(first[0], "visibility_level_se");
    EXPECT_GT(error, 0);
    EXPECT_LT(error, 0.02 * level);
    // Far from the criterion: one pass whatever -vp allows.
    EXPECT_EQ(csv(run(line + "-vp 4 sign.rad lamp.rad").out)[0].at("visibility_level_se"), first[0].at("visibility_level_se"));
    std::ostringstream near;
    near << "-vl " << level << " -vp 2 ";
    std::vector<Row> second = csv(run(line + near.str() + "sign.rad lamp.rad").out);
    double ratio = error / number(second[0], "visibility_level_se");
    EXPECT_GT(ratio, 1.2);
    EXPECT_LT(ratio, 1.7);
}

// Maps over a grid: one picture per instant and sign, its pixels the visibility level (0 where a wall hides the
// sign), and the instant through which it stayed visible, by the light and by Jin's law.
TEST_F(Vismap, MapsOverAGrid) {
    // A screen at x 3…3.1 hides the sign from the grid's cells of y < 0.
    std::ofstream(dir_ / "screen.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                                          "grey polygon screen 0 0 12  3 -4 0  3 0 0  3 0 4  3 -4 4\n";
    Output r = run("vismap -S signs.txt -g 4 -2 8 2 1 1.75 -o map -T 0,10 -ab 0 -me .2 .2 .2 -ma 0 0 0 sign.rad screen.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<Row> rows = csv(r.out);
    ASSERT_EQ(rows.size(), 32u);  // 16 cells, two instants
    for (const char* name : {"map_sign_0.hdr", "map_sign_10.hdr", "map_sign_until.hdr", "map_sign_jin_until.hdr",
                             "map_any_until.hdr"}) {
        brume::Picture p = brume::readPicture((dir_ / name).string());
        ASSERT_EQ(p.width, 4) << name;
        ASSERT_EQ(p.height, 4) << name;
        for (const Row& row : rows) {
            if (row.at("instant_s") != "10") continue;
            int column = int(number(row, "x") - 4), rowIndex = int(2 - number(row, "y"));
            float v = p.at(column, rowIndex)[0];
            bool hidden = number(row, "y") < 0;
            EXPECT_EQ(row.at("verdict"), hidden ? "hidden" : "visible") << row.at("observer");
            if (std::string(name) == "map_sign_10.hdr") {
                EXPECT_NEAR(v, hidden ? 0 : number(row, "visibility_level"), 0.005 * v) << row.at("observer");
            } else if (std::string(name).find("until") != std::string::npos) {
                EXPECT_NEAR(v, hidden ? 0 : 10, 0.05) << name << " " << row.at("observer");  // RGBE: 8-bit mantissas
            }
        }
    }
}

// Smoke that thickens linearly between key frames (density 1 at 10 s, 3 at 20 s, K .8 /m, 5 m from the sign):
// the optical depth is 4 then 12, so Jin's S = 8/K reaches the distance at 15 s exactly, which the losses
// interpolate from the two instants; the report's other files say the same.
TEST_F(Vismap, LossesAreInterpolatedBetweenInstantsAndReported) {
    namespace mt = brume::medium::testing;
    mt::writeGrid(dir_ / "thin.vdb", mt::boxGrid({-4, -12, -2}, {24, 12, 12}, 1.0f, 0.5));
    mt::writeGrid(dir_ / "thick.vdb", mt::boxGrid({-4, -12, -2}, {24, 12, 12}, 3.0f, 0.5));
    std::ofstream(dir_ / "smoke.rad") << "void smoke s 4 10 thin.vdb 20 thick.vdb 0 3 .8 .8 .8\n";
    waypoints("door 5 0 1.75\n");
    Output r = run("vismap -S signs.txt -wp route.txt -T 10,20 -o study -ab 0 -vr 4 sign.rad smoke.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<Row> rows = csv(r.out);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(number(rows[0], "optical_depth"), 4, 1e-3);
    EXPECT_NEAR(number(rows[1], "optical_depth"), 12, 1e-3);
    EXPECT_EQ(rows[1].at("jin_verdict"), "not-visible");
    std::vector<Row> lost = csv(brume_test::slurp(dir_ / "study_lost.csv"));
    ASSERT_EQ(lost.size(), 6u);  // light and Jin, for the sign, for any sign, and for the route
    EXPECT_EQ(lost[4].at("observer"), "route:door");
    for (const Row& l : lost) {
        if (l.at("criterion") != "jin") continue;
        EXPECT_EQ(l.at("how"), l.at("sign") == "sign" ? "interpolated" : "bracketed") << l.at("sign") << l.at("observer");
        EXPECT_EQ(l.at("after_s"), "10");
        EXPECT_EQ(l.at("before_s"), "20");
        if (l.at("sign") == "sign") {
            EXPECT_NEAR(number(l, "lost_s"), 15, 1e-3);
        }
    }
    std::vector<Row> summary = csv(brume_test::slurp(dir_ / "study_summary.csv"));
    ASSERT_EQ(summary.size(), 4u);  // two instants, the sign and any
    EXPECT_EQ(summary[0].at("visible_jin"), "1");
    EXPECT_EQ(summary[2].at("visible_jin"), "0");
    const std::string json = brume_test::slurp(dir_ / "study.json");
    EXPECT_NE(json.find("\"visibility_level\": 10"), std::string::npos) << json;
    EXPECT_NE(json.find("\"jin_C\": 8"), std::string::npos) << json;
    EXPECT_NE(json.find("\"version\": \"Brume "), std::string::npos) << json;
    // Clear air: no Jin's distance (an empty field, not inf).
    Output clear = run("vismap -S signs.txt -wp route.txt -ab 0 -vr 4 sign.rad");
    ASSERT_EQ(clear.status, 0) << clear.err;
    EXPECT_EQ(csv(clear.out)[0].at("jin_distance_m"), "");
    EXPECT_EQ(clear.out.find("inf"), std::string::npos);
}

// Inputs likely wrong are warned of before the study runs: a sign whose front faces no eye (its vertex order),
// eyes inside a solid (a closed box of outward faces around one of them).
TEST_F(Vismap, WarnsOfSignsFacingNoEyeAndEyesInsideSolids) {
    std::ofstream(dir_ / "box.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                                       "grey polygon x0 0 0 12  3 -1 1  3 -1 2  3 1 2  3 1 1\n"
                                       "grey polygon x1 0 0 12  4 -1 1  4 1 1  4 1 2  4 -1 2\n"
                                       "grey polygon y0 0 0 12  3 -1 1  4 -1 1  4 -1 2  3 -1 2\n"
                                       "grey polygon y1 0 0 12  3 1 1  3 1 2  4 1 2  4 1 1\n"
                                       "grey polygon z0 0 0 12  3 -1 1  3 1 1  4 1 1  4 -1 1\n"
                                       "grey polygon z1 0 0 12  3 -1 2  4 -1 2  4 1 2  3 1 2\n";
    waypoints("walled 3.5 0 1.5\nbehind -2 0 1.75\nopen 6 3 1.75\n");
    Output r = run("vismap -S signs.txt -wp route.txt -ab 0 -vr 1 sign.rad box.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("1 of 3 eyes lie inside solids (walled)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("faces away"), std::string::npos) << r.err;
    waypoints("behind -2 0 1.75\n");
    r = run("vismap -S signs.txt -wp route.txt -ab 0 -vr 1 sign.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("sign 'sign' faces away from every eye"), std::string::npos) << r.err;
    EXPECT_EQ(csv(r.out)[0].at("verdict"), "behind");
}

// -vj: Jin's law alone, no light traced: the same optical depths and Jin's verdicts as the full study, the light's
// columns empty, signs hidden by the scene's surfaces across the line to their centre.
TEST_F(Vismap, JinAloneAgreesWithTheFullStudysJinColumns) {
    std::ofstream(dir_ / "screen.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                                          "grey polygon screen 0 0 12  3 -4 0  3 0 0  3 0 4  3 -4 4\n";
    const std::string grid = "-S signs.txt -g 4 -2 8 2 1 1.75 -ab 0 -me .2 .2 .2 -ma 0 0 0 sign.rad screen.rad";
    Output full = run("vismap " + grid), alone = run("vismap -vj " + grid);
    ASSERT_EQ(full.status, 0) << full.err;
    ASSERT_EQ(alone.status, 0) << alone.err;
    std::vector<Row> a = csv(full.out), b = csv(alone.out);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].at("optical_depth"), b[i].at("optical_depth"));
        EXPECT_EQ(a[i].at("jin_verdict"), b[i].at("jin_verdict"));
        EXPECT_EQ(b[i].at("verdict"), a[i].at("verdict") == "hidden" ? "hidden" : "not-traced") << a[i].at("observer");
        EXPECT_EQ(b[i].at("sign_cd_m2"), "");
        EXPECT_EQ(b[i].at("visibility_level"), "");
    }
}

TEST_F(Vismap, BadInputIsNamedAndWritesNothing) {
    waypoints("a 2 0 1.75\n");
    auto error = [&](const std::string& options, const std::string& signs) {
        std::ofstream(dir_ / "bad_signs.txt") << signs;
        return run("vismap " + options + " sign.rad");
    };
    Output r = error("-S bad_signs.txt -wp route.txt", "sign emitting\nexit emitting\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "vismap: bad_signs.txt:2: sign 'exit': no polygon of this name in the scene\n");
    r = error("-S bad_signs.txt -wp route.txt", "sign glowing\n");
    EXPECT_EQ(r.err, "vismap: bad_signs.txt:1: sign 'sign': kind 'glowing' is neither emitting nor reflecting\n");
    r = error("-S bad_signs.txt -wp route.txt -g 0 0 1 1 1 1", "sign emitting\n");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("either on a grid (-g) or at waypoints (-wp)"), std::string::npos) << r.err;
    r = error("-S bad_signs.txt -wp route.txt -vc 1.5", "sign emitting\n");
    EXPECT_NE(r.err.find("-vc: a share, from 0 to 1"), std::string::npos) << r.err;
    r = error("-S bad_signs.txt -wp route.txt -T 20,10", "sign emitting\n");
    EXPECT_NE(r.err.find("-T: instants must increase"), std::string::npos) << r.err;
    for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
             {"-wp route.txt", "no signs (-S)"},
             {"-S bad_signs.txt -wp route.txt -vr 0", "-vr: at least one ray"},
             {"-S bad_signs.txt -wp route.txt -vp 0", "-vp: at least one pass"},
             {"-S bad_signs.txt -wp route.txt -vx 0", "-vx: a distance > 0"},
             {"-S bad_signs.txt -wp route.txt -vs -1", "-vs: a distance >= 0"},
             {"-S bad_signs.txt -wp route.txt -i", "-i: a study traces the light that reaches the eye"}}) {
        r = error(options, "sign emitting\n");
        EXPECT_NE(r.status, 0) << options;
        EXPECT_EQ(r.out, "") << options;
        EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
    }
    r = error("-S nowhere.txt -wp route.txt", "");
    EXPECT_EQ(r.err, "vismap: nowhere.txt: cannot be opened\n");
    EXPECT_EQ(r.out, "");
    // An instant outside the smoke's key frames: no data there, not the nearest frame's smoke; nothing written.
    using namespace brume::medium::testing;
    writeGrid(dir_ / "thin.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 1.0f, 0.1));
    writeGrid(dir_ / "thick.vdb", boxGrid({0, 0, 0}, {9, 9, 9}, 3.0f, 0.1));
    std::ofstream(dir_ / "smoke.rad") << "void smoke s 4 10 thin.vdb 20 thick.vdb 0 3 .1 .1 .1\n";
    r = error("-S bad_signs.txt -wp route.txt -T 10,30 smoke.rad", "sign emitting\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "vismap: smoke.rad:1: smoke 's': no data at 30 s, outside its 2 key frames (10 to 20 s; -T sets "
                     "the instant)\n");
}

}  // namespace
