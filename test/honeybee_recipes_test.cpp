// Honeybee's annual-daylight recipes (pollination's, with honeybee-radiance's CLI) run through with their own
// command lines on Brume's programs, against the same recipes on Radiance's programs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "rcontrib";
const fs::path kWeather = fs::path(BRUME_SHARED_DATA) / "weather";

// A Honeybee model folder of test/data/rcontrib's office (scene/envelope.mat and .rad, its black-out
// envelope.blk: opaque modifiers black, the glazing as it is; grid/office.pts, 16 sensors) and the sky dome
// as `honeybee-radiance sky skydome` writes it, in resources/.
fs::path modelFolder(const std::string& name) {
    fs::path dir = brume_test::scratchDir(name);
    fs::create_directories(dir / "model/scene");
    fs::create_directories(dir / "model/grid");
    fs::create_directories(dir / "resources");
    fs::copy_file(kData / "materials.rad", dir / "model/scene/envelope.mat", fs::copy_options::overwrite_existing);
    fs::copy_file(kData / "office.rad", dir / "model/scene/envelope.rad", fs::copy_options::overwrite_existing);
    fs::copy_file(kData / "grid16.pts", dir / "model/grid/office.pts", fs::copy_options::overwrite_existing);
    std::ofstream(dir / "model/scene/envelope.blk") << "void plastic wall_mat 0 0 5 0 0 0 0 0\n"
                                                       "void plastic floor_mat 0 0 5 0 0 0 0 0\n"
                                                       "void plastic ceiling_mat 0 0 5 0 0 0 0 0\n"
                                                       "void plastic ext_mat 0 0 5 0 0 0 0 0\n"
                                                       "void glass glazing 0 0 3 0.654 0.654 0.654\n";
    std::ofstream(dir / "resources/sky.dome") << "#@rfluxmtx h=u u=Y\nvoid glow ground_glow\n0\n0\n4 0.2 0.2 0.2 0\n\n"
                                                 "ground_glow source ground\n0\n0\n4 0 0 -1 180\n\n"
                                                 "#@rfluxmtx h=r1 u=Y\nvoid glow sky_glow\n0\n0\n4 1 1 1 0\n\n"
                                                 "sky_glow source sky\n0\n0\n4 0 0 1 180\n";
    return dir;
}

// The year, the octree and the sky matrix of the sun-up hours, and the hours from the suns' names (Honeybee's
// ParseSunUpHours reads its own sun modifiers so).
std::string preparation() {
    return "epw2wea '" + (kWeather / "chicago.epw").string() + "' resources/sky.wea\n"
           "(cd model && oconv -r 32768 -f scene/envelope.mat scene/envelope.rad > ../resources/scene.oct) || exit\n"
           "gendaymtx -u -r 0.0 -O0 resources/sky.wea > resources/sky.mtx || exit\n"
           "gendaymtx -u -D resources/suns.rad -M resources/suns.mod resources/sky.wea > /dev/null || exit\n"
           "sed 's/solar//' resources/suns.mod | awk '{print $1 / 60}' > resources/sun-up-hours.txt\n";
}

// The total sky's coefficients piped into rmtxop, as Honeybee writes them (its radiance_parameters here -ab 10
// -ad 4096 -lw 1e-05 -u-: its default -ab 2 truncates this room's light by a third; -u- makes the test's
// sample the same on every run).
const char* const kTotalSky =
    "rfluxmtx -aa 0.0 -ab 10 -ad 4096 -lw 1e-05 -u- -I -c 1 -faf -y 16 - \"resources/sky.dome\" -i "
    "\"\"\"resources/scene.oct\"\"\" < \"model/grid/office.pts\" | rmtxop -ff - \"resources/sky.mtx\" -c 47.4 119.9 11.6 ";

std::vector<std::vector<double>> metricsOf(std::istream& in) {
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == 's') continue;
        std::istringstream fields(line);
        rows.emplace_back();
        for (std::string f; std::getline(fields, f, ',');) rows.back().push_back(std::stod(f));
    }
    return rows;
}

// Each sensor's DA, cDA and UDI bands (daymetrics' CSV) within `points` of the reference file's; its cDA
// within `cdaPoints` where the reference has no column of negative hours or none in it.
void expectMetricsNear(const std::string& csv, const std::string& reference, double points, double cdaPoints) {
    std::istringstream out(csv);
    std::ifstream ref(kData / reference);
    std::vector<std::vector<double>> brume = metricsOf(out), radiance = metricsOf(ref);
    ASSERT_EQ(brume.size(), 16u) << csv;
    ASSERT_EQ(radiance.size(), 16u);
    for (size_t s = 0; s < 16; ++s)
        for (size_t m = 1; m < 6; ++m) {
            if (m == 2 && radiance[s].size() > 6 && radiance[s][6] > 0) continue;
            EXPECT_NEAR(brume[s][m], radiance[s][m], m == 2 ? cdaPoints : points) << "sensor " << s << " column " << m;
        }
}

}  // namespace

// Honeybee's annual-daylight recipe (pollination/annual-daylight 2025, honeybee-radiance's CLI) runs these
// Radiance command lines, word for word but the file names and the ray-tracing parameters: the octree from the
// model folder, the sky matrix of the sun-up hours, the sky dome, and the coefficients piped into rmtxop; the
// metrics from daymetrics, Honeybee's postprocess definitions. Against the same recipe run on Radiance's
// programs (test/data/rcontrib/office_recipe_metrics.csv, its own error 0.5 % RMS in annual means): each
// sensor's DA, cDA and UDI bands within 2 points (over three independent runs at these parameters the
// largest difference was 1.5 points, at the back of the room; at -ab 7 -ad 2048, 3.0). sDA is not compared on 16 sensors: one sensor is 6.25
// points, and sensor 14's DA lies at 49.9 %, on the 50 % line.
TEST(HoneybeeRecipes, AnnualDaylightRunsOnBrumesPrograms) {
    fs::path dir = modelFolder("honeybee_recipe");
    Output o = brume_test::runBrume(preparation() + kTotalSky + "> \"results.ill\" || exit\n"
                                    "daymetrics -hours resources/sun-up-hours.txt results.ill\n", dir);
    ASSERT_EQ(o.status, 0) << o.err;
    expectMetricsNear(o.out, "office_recipe_metrics.csv", 2.0, 2.0);
}

// Honeybee's annual-daylight-enhanced recipe (pollination/annual-daylight-enhanced, its two-phase daylight
// coefficients): the direct sun from one source per sun-up hour (rcontrib -V+ -M suns.mod through the
// blacked-out octree with the suns, -ab 0), the total sky less the direct sky (rfluxmtx -ab 1 through the
// blacked-out octree, gendaymtx -d), Honeybee's numpy sum done by rmtxop. The suns are gendaymtx -D's
// (Honeybee writes its own sun path, the same suns). Against the same recipe on Radiance's programs at -ad 400000
// (office_enhanced_recipe_metrics.csv): each sensor's DA and UDI bands within 2.5 points (Radiance's own DA of
// the sensors on the 50 % line moved 0.9 point from -ad 50000 to 400000; Brume's at -ad 4096, 1.5 over three
// runs of the other recipe), cDA within 2 where Radiance's total less direct sky never went negative (its two
// noisy estimates of the sun's patches: up to 44 such hours at a sensor, each pulling cDA down; Brume's aimed
// samples gave none).
TEST(HoneybeeRecipes, AnnualDaylightEnhancedRunsOnBrumesPrograms) {
    fs::path dir = modelFolder("honeybee_enhanced_recipe");
    std::string recipe =
        preparation() +
        "(cd model && oconv -r 32768 -f scene/envelope.blk scene/envelope.rad > ../resources/scene_direct.oct) || exit\n"
        "(cd model && oconv -r 32768 -f scene/envelope.blk scene/envelope.rad ../resources/suns.rad "
        "> ../resources/scene_with_suns.oct) || exit\n"
        "gendaymtx -u -r 0.0 -d -O0 resources/sky.wea > resources/sky_direct.mtx || exit\n"
        "rcontrib -aa 0.0 -ab 0 -ad 4096 -lw 1e-05 -u- -I -faf -dc 1.0 -dt 0.0 -dj 0.0 -V+ -y 16 -M ./resources/suns.mod "
        "resources/scene_with_suns.oct < model/grid/office.pts | rmtxop -ff - -c 47.4 119.9 11.6 > sun.ill || exit\n"
        "rfluxmtx -aa 0.0 -ab 1 -ad 4096 -lw 1e-05 -u- -I -c 1 -faf -y 16 - \"resources/sky.dome\" -i "
        "\"\"\"resources/scene_direct.oct\"\"\" < \"model/grid/office.pts\" | rmtxop -ff - \"resources/sky_direct.mtx\" "
        "-c 47.4 119.9 11.6 > direct.ill || exit\n" +
        kTotalSky + "> total.ill || exit\n"
        "rmtxop -ff total.ill + -s -1 direct.ill + sun.ill > results.ill || exit\n"
        "daymetrics -hours resources/sun-up-hours.txt results.ill\n";
    Output o = brume_test::runBrume(recipe, dir);
    ASSERT_EQ(o.status, 0) << o.err;
    expectMetricsNear(o.out, "office_enhanced_recipe_metrics.csv", 2.5, 2.0);
}
