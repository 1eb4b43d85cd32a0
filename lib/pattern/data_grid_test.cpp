#include "pattern/data_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "util/error.h"

using namespace brume;

namespace {

std::string writeFile(const std::string& name, const std::string& text) {
    std::string path = testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

float at(const DataGrid& g, std::vector<double> p) {
    float v;
    g.interpolate(p, &v);
    return v;
}

}  // namespace

// A 2-D file with one even and one uneven axis: values of f(x, y) = x + 10 y are reproduced exactly at and
// between nodes, because multilinear interpolation is exact for functions linear along each axis.
TEST(DataGrid, InterpolationIsExactForLinearData) {
    std::string path = writeFile("grid_linear.dat",
                                 "2  # dimensions\n0 2 3\n0 0 4  0 1 3 7\n"
                                 "0 10 30 70\n1 11 31 71\n2 12 32 72\n");
    DataGrid g = DataGrid::readDataFile(path);
    ASSERT_EQ(g.dimensions(), 2);
    EXPECT_FLOAT_EQ(at(g, {1, 3}), 31);
    EXPECT_FLOAT_EQ(at(g, {0.5, 2}), 20.5f);
    EXPECT_FLOAT_EQ(at(g, {1.75, 5}), 51.75f);
    std::remove(path.c_str());
}

// Decreasing axes (e.g. angles listed from 180 down to 0) are as good as increasing ones.
TEST(DataGrid, DecreasingAxisPointsWork) {
    DataGrid g({DataGrid::Axis{180, 0, 3, {180, 90, 0}}}, 1, {2, 1, 0});
    EXPECT_FLOAT_EQ(at(g, {45}), 0.5f);
    EXPECT_FLOAT_EQ(at(g, {135}), 1.5f);
}

// Radiance's rule outside the grid: linear for one more division, then c/(distance) tapering to zero.
TEST(DataGrid, ExtrapolatesOneDivisionThenTapers) {
    DataGrid g({DataGrid::Axis{0, 1, 2, {}}}, 1, {1, 2});
    EXPECT_FLOAT_EQ(at(g, {1.5}), 2.5f);
    EXPECT_FLOAT_EQ(at(g, {-0.5}), 0.5f);
    // x = 4 (three divisions out): c0 = 1/(i−1−x) = −1/5, c1 = 2/5.
    EXPECT_FLOAT_EQ(at(g, {4}), -0.2f + 0.8f);
    EXPECT_NEAR(at(g, {1e12}), 0, 1e-9);
    EXPECT_EQ(at(g, {std::nan("")}), 0);
}

// Pictures: the smaller side spans 0…1; the first row of nodes is the picture's bottom row.
TEST(DataGrid, PicturesMapToUnitHeightCoordinates) {
    Picture p;
    p.width = 4;
    p.height = 2;
    p.pixels.assign(4 * 2 * 3, 0.f);
    p.at(3, 0)[0] = 1;  // top right
    DataGrid g = DataGrid::fromPicture(p);
    ASSERT_EQ(g.channels(), 3);
    EXPECT_DOUBLE_EQ(g.axes()[1].end, 2.0);  // u spans the aspect ratio
    float rgb[3];
    g.interpolate(std::vector<double>{1, 2}, rgb);
    EXPECT_FLOAT_EQ(rgb[0], 1);
    g.interpolate(std::vector<double>{0, 2}, rgb);
    EXPECT_FLOAT_EQ(rgb[0], 0);
}

// Values near the largest float, extrapolated past it, stay finite.
TEST(DataGrid, ExtrapolatingHugeValuesStaysFinite) {
    DataGrid grid({DataGrid::Axis{0, 1, 2, {}}}, 1, {0.f, 3e38f});
    float v;
    double x = 1.9;
    grid.interpolate(std::span<const double>(&x, 1), &v);
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GT(v, 3e38f);
}

TEST(DataGrid, MalformedFilesAreErrorsWithTheirLine) {
    struct Case {
        const char* text;
        const char* message;
    } cases[] = {{"0\n", "bad number of dimensions"},
                 {"1\n0 1 1\n5\n", "bad node count"},
                 {"1\n0 1 3\n1 2\n", "unexpected end of file"},
                 {"1\n0 0 3 1 3 2\n1 2 3\n", "not monotonic"},
                 {"1\n0 1 2\n1 x\n", ":3: bad data value"},
                 {"1\n0 1 2\n1 1e39\n", ":3: data value beyond single precision"},
                 {"2\n0 1 30000\n0 1 30000\n1 2\n", "unexpected end of file"}};
    for (const Case& c : cases) {
        std::string path = writeFile("grid_bad.dat", c.text);
        try {
            DataGrid::readDataFile(path);
            ADD_FAILURE() << c.text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
        }
        std::remove(path.c_str());
    }
    EXPECT_THROW(DataGrid::readDataFile("no_such_file.dat"), Error);
}
