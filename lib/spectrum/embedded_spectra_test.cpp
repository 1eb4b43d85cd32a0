#include "spectrum/embedded_spectra.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pattern/data_grid.h"
#include "ray_path_dir.h"
#include "spectrum/cie_tables.h"
#include "util/error.h"

namespace brume {
namespace {

// One column of a CIE CSV kept for tests (test/data/cie), indexed by wavelength from 380 nm.
std::vector<double> csvColumn(const std::string& file, int column) {
    std::ifstream in(std::string(BRUME_TEST_DATA) + "/cie/" + file);
    EXPECT_TRUE(in) << file;
    std::vector<double> values;
    for (std::string line; std::getline(in, line);) {
        std::istringstream cells(line);
        std::string cell;
        for (int i = 0; i <= column; ++i) std::getline(cells, cell, ',');
        values.push_back(std::stod(cell));
    }
    return values;
}

double at(const DataGrid& grid, double nm) {
    float v;
    grid.interpolate(std::span<const double>(&nm, 1), &v);
    return v;
}

std::pair<double, double> chromaticity(const DataGrid& grid) {
    double x = 0, y = 0, z = 0;
    for (int nm = 380; nm <= 780; ++nm) {
        double s = at(grid, nm);
        x += s * cieX().at(nm), y += s * cieY().at(nm), z += s * cieZ().at(nm);
    }
    return {x / (x + y + z), y / (x + y + z)};
}

// Found by bare name with RAYPATH naming only an empty directory: the embedded copy. Values are stored
// as floats, hence the relative 1e-6.
DataGrid shipped(const std::string& name) {
    RayPathDir empty;
    return DataGrid::readDataFile(name);
}

void expectColumn(const DataGrid& grid, const std::vector<double>& values, double first) {
    ASSERT_EQ(grid.dimensions(), 1);
    EXPECT_EQ(grid.axes()[0].begin, first);
    EXPECT_EQ(grid.axes()[0].count, int(values.size()));
    for (size_t i = 0; i < values.size(); ++i)
        EXPECT_NEAR(at(grid, first + double(i)), values[i], 1e-6 * values[i] + 1e-30) << first + double(i) << " nm";
}

TEST(EmbeddedSpectra, StandardIlluminantsAreTheCieTables) {
    for (auto [name, table] : {std::pair{"cie_a.dat", &illuminantA()}, std::pair{"cie_d65.dat", &illuminantD65()}})
        expectColumn(shipped(name), table->values, table->first);
}

TEST(EmbeddedSpectra, FluorescentAndLedIlluminantsAreTheCieTables) {
    for (int k = 1; k <= 12; ++k)
        expectColumn(shipped("cie_f" + std::to_string(k) + ".dat"), csvColumn("CIE_illum_FLs_1nm.csv", k), 380);
    const char* leds[] = {"b1", "b2", "b3", "b4", "b5", "bh1", "rgb1", "v1", "v2"};
    for (int k = 0; k < 9; ++k)
        expectColumn(shipped(std::string("cie_led_") + leds[k] + ".dat"), csvColumn("CIE_illum_LEDs_1nm.csv", k + 1), 380);
}

// CIE 15:2018 Tables 10.3 and 12.1 give these to four decimals: half a unit (5e-5) of rounding and as
// much again for float storage and the 1 nm sums.
TEST(EmbeddedSpectra, ChromaticitiesAreTheCies) {
    struct Case {
        const char* name;
        double x, y;
    } cases[] = {{"cie_f2.dat", 0.3721, 0.3751}, {"cie_f11.dat", 0.3805, 0.3769}, {"cie_led_b3.dat", 0.3756, 0.3723}};
    for (const Case& c : cases) {
        auto [x, y] = chromaticity(shipped(c.name));
        EXPECT_NEAR(x, c.x, 1e-4) << c.name;
        EXPECT_NEAR(y, c.y, 1e-4) << c.name;
    }
}

TEST(EmbeddedSpectra, AFileOnRayPathComesFirst) {
    RayPathDir dir;
    dir.write("cie_a.dat", "1 380 780 2 5 7\n");
    DataGrid grid = DataGrid::readDataFile("cie_a.dat");
    EXPECT_EQ(grid.axes()[0].count, 2);
    EXPECT_THROW(DataGrid::readDataFile("cie_nothing.dat"), Error);
}

TEST(EmbeddedSpectra, EveryFileNamesItsSource) {
    for (const EmbeddedFile& f : embeddedSpectrumFiles()) {
        EXPECT_TRUE(f.text.starts_with("# CIE ")) << f.name;
        EXPECT_NE(f.text.find("CC BY-SA 4.0"), std::string_view::npos) << f.name;
    }
    EXPECT_EQ(embeddedSpectrumFiles().size(), 23u);
}

}  // namespace
}  // namespace brume
