#include "fds/fds_quantity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "fds/plot3d_file.h"
#include "fds/slice_file.h"
#include "fds/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

namespace brume {
namespace {

using Voxels = std::map<std::tuple<int, int, int>, float>;

// The mean of the 8 cells around node (i, j, k) of a cell-centred lattice: what FDS writes at a node.
double cornerMean(Voxels& c, int i, int j, int k) {
    double mean = 0;
    for (int d = 0; d < 8; ++d) mean += c[{i - 1 + (d & 1), j - 1 + (d >> 1 & 1), k - 1 + (d >> 2)}] / 8.0;
    return mean;
}

Voxels byIndex(const LatticeVoxels& v) {
    Voxels out;
    for (const auto& [i, value] : v.values) out[{i.x, i.y, i.z}] = value;
    return out;
}

// Mesh `mesh`'s (1 or 2) cell (i, j, k) of the committed case's cell-centred slice `suffix` at frame `frame`:
// the files' index 0 of each axis is a ghost cell, so cell i is value i + 1 of 11.
float sliceCell(int mesh, int suffix, size_t frame, int i, int j, int k) {
    SliceFile f = readSlice(fds_test::twoMeshCase() + "/two_mesh_smoke_" + std::to_string(mesh) + "_" +
                            std::to_string(suffix) + ".sf");
    return f.frames.at(frame).values[size_t((i + 1) + 11 * ((j + 1) + 11 * (k + 1)))];
}

TEST(FdsQuantity, AssemblesTwoMeshesOfARealCaseFromTheirCellCentredSlices) {
    SmvIndex smv = readSmv(fds_test::twoMeshCase() + "/two_mesh_smoke.smv");
    FdsQuantity soot(smv, "SOOT DENSITY");
    EXPECT_EQ(soot.units(), "kg/m3");
    EXPECT_EQ(soot.source(), "cell-centred 3D slices");
    ASSERT_EQ(soot.times().size(), 11u);  // DT_SL3D = 2 s over 20 s
    for (size_t f = 0; f < soot.times().size(); ++f) EXPECT_NEAR(soot.times()[f], 2.0 * double(f), 0.05);
    LatticeVoxels v = soot.at(soot.times()[10]);
    EXPECT_EQ(v.origin, glm::dvec3(0.05));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.spacing[a], 0.1, 1e-6);
    Voxels cells = byIndex(v);
    // Every cell of both meshes is FDS's own value: mesh "right" starts at lattice index 10.
    for (auto [i, j, k] : {std::tuple{3, 5, 9}, {9, 2, 8}, {10, 2, 8}, {19, 9, 9}, {14, 4, 0}}) {
        float fds = i < 10 ? sliceCell(1, 1, 10, i, j, k) : sliceCell(2, 1, 10, i - 10, j, k);
        EXPECT_GT(fds, 0) << i << " " << j << " " << k;
        EXPECT_EQ((cells[{i, j, k}]), fds) << i << " " << j << " " << k;
    }
    for (const auto& [i, value] : v.values) {
        EXPECT_TRUE(i.x >= 0 && i.x < 20 && i.y >= 0 && i.y < 10 && i.z >= 0 && i.z < 10);
        EXPECT_GT(value, 0);
    }
    // Between frames, linear in time.
    double mid = 0.5 * (soot.times()[4] + soot.times()[5]);
    float a = byIndex(soot.at(soot.times()[4]))[{12, 5, 9}], b = byIndex(soot.at(soot.times()[5]))[{12, 5, 9}];
    EXPECT_NEAR((byIndex(soot.at(mid))[{12, 5, 9}]), 0.5f * (a + b), 1e-6f * (a + b));
    EXPECT_THROW(soot.at(21), Error);
}

TEST(FdsQuantity, TemperaturesInKelvinAndExtinctionIsSootTimesFdsMassExtinction) {
    SmvIndex smv = readSmv(fds_test::twoMeshCase() + "/two_mesh_smoke.smv");
    FdsQuantity temperature(smv, "TEMPERATURE");
    EXPECT_EQ(temperature.units(), "K");
    LatticeVoxels start = temperature.at(0);
    EXPECT_EQ(start.values.size(), 2000u);
    for (const auto& [i, t] : start.values) EXPECT_NEAR(t, 293.15, 0.01);  // FDS's ambient, 20 °C
    float hottest = 0;
    for (const auto& [i, t] : temperature.at(20).values) hottest = std::max(hottest, t);
    EXPECT_GT(hottest, 600);  // over a 50 kW burner
    // The extinction slice is 8700 m²/kg times the soot slice (FDS's default mass extinction), cell for cell.
    Voxels soot = byIndex(FdsQuantity(smv, "SOOT DENSITY").at(20));
    Voxels extinction = byIndex(FdsQuantity(smv, "SOOT EXTINCTION COEFFICIENT").at(20));
    ASSERT_EQ(soot.size(), extinction.size());
    for (const auto& [i, k] : extinction) EXPECT_NEAR(k, 8700 * soot[i], 1e-5 * k);
}

// A mesh of 0.2 m cells beside one of 0.1 m: the lattice is the finer one's, and each coarse cell fills 2 x 2 x 2
// of its voxels with FDS's value for it; the 3D smoke files (node values) of such meshes are refused.
TEST(FdsQuantity, CoarserMeshesFillSeveralVoxelsPerCell) {
    const std::string dir = std::string(BRUME_TEST_DATA) + "/fds/two_res";
    SmvIndex smv = readSmv(dir + "/two_res.smv");
    FdsQuantity soot(smv, "SOOT DENSITY");
    LatticeVoxels v = soot.at(soot.times().back());
    EXPECT_EQ(v.origin, glm::dvec3(0.05));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.spacing[a], 0.1, 1e-6);
    Voxels cells = byIndex(v);
    SliceFile coarse = readSlice(dir + "/two_res_2_1.sf"), fine = readSlice(dir + "/two_res_1_1.sf");
    int compared = 0;
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) {
                float fds = coarse.frames.back().values[size_t((i + 1) + 6 * ((j + 1) + 6 * (k + 1)))];
                if (fds == 0) continue;
                for (int d = 0; d < 8; ++d) {
                    std::tuple<int, int, int> at{10 + 2 * i + (d & 1), 2 * j + (d >> 1 & 1), 2 * k + (d >> 2)};
                    ASSERT_EQ(cells[at], fds) << i << " " << j << " " << k;
                }
                ++compared;
            }
    EXPECT_GT(compared, 50);
    EXPECT_EQ((cells[{3, 4, 9}]), fine.frames.back().values[size_t(4 + 11 * (5 + 11 * 10))]);
    for (const auto& [i, value] : v.values) EXPECT_TRUE(i.x >= 0 && i.x < 20 && i.y >= 0 && i.y < 10 && i.z >= 0 && i.z < 10);
    std::erase_if(smv.files, [](const FdsFile& f) { return f.kind == FdsFile::Kind::Slice; });
    try {
        FdsQuantity nodes(smv, "SOOT DENSITY");
        ADD_FAILURE() << "3D smoke files of meshes of two resolutions were taken";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("meshes of different resolutions are imported from cell-centred slices only"),
                  std::string::npos)
            << e.what();
    }
}

// What the import refuses, named: a quantity the case lacks, a stretched mesh, a mesh off the first one's lattice,
// a slice whose index range is not the one the index lists. Each from the committed case's index, one line changed.
TEST(FdsQuantity, RefusesCasesItCannotPutOnOneLattice) {
    // A copy of the case, so that edited indexes lie beside its files without writing into the source tree.
    const std::string dir = brume_test::scratchDir("fds_edited").string();
    for (const auto& file : std::filesystem::directory_iterator(fds_test::twoMeshCase()))
        std::filesystem::copy_file(file.path(), dir + "/" + file.path().filename().string(),
                                   std::filesystem::copy_options::overwrite_existing);
    std::ifstream in(dir + "/two_mesh_smoke.smv");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    auto errorWith = [&](const std::string& from, const std::string& to, size_t occurrence,
                         const std::string& quantity = "SOOT DENSITY") {
        std::string edited = text;
        size_t at = 0;
        for (size_t k = 0; k <= occurrence; ++k) at = edited.find(from, k ? at + 1 : 0);
        if (at == std::string::npos) return std::string("'" + from + "' not found");
        edited.replace(at, from.size(), to);
        const std::string path = dir + "/edited.smv";
        std::ofstream(path) << edited;
        std::string message = "no error";
        try {
            FdsQuantity(readSmv(path), quantity);
        } catch (const Error& e) {
            message = e.what();
        }
        std::filesystem::remove(path);
        for (size_t p = message.find(path); p != std::string::npos; p = message.find(path)) message.replace(p, path.size(), "case.smv");
        for (size_t p = message.find(dir + "/"); p != std::string::npos; p = message.find(dir + "/")) message.erase(p, dir.size() + 1);
        return message;
    };
    // The case's 3D smoke files of HRRPUV and temperature are listed but not kept: only files that are there count.
    EXPECT_EQ(errorWith("", "", 0, "HRRPUV"),
              "case.smv: no cell-centred 3D slice of 'HRRPUV' (the case has 'SOOT DENSITY', 'SOOT EXTINCTION COEFFICIENT', "
              "'TEMPERATURE')");
    EXPECT_EQ(errorWith("    5       1.50000", "    5       1.55000", 0),
              "case.smv: mesh 2 (right) is stretched: only meshes of even cells are imported");
    EXPECT_EQ(errorWith("OFFSET\n      0.00000", "OFFSET\n      0.05000", 1),
              "case.smv: mesh 2 is not on the lattice of the finest mesh's cells");
    EXPECT_EQ(errorWith("&     0    10     0    10     0    10 !      1      1", "&     0    10     0    10     0     9 !      1      1", 0),
              "two_mesh_smoke_1_1.sf: its index range is not the one case.smv lists");
}

// With the slices set aside, soot comes from the 3D smoke files: node values from 8-bit opacities. Each node's
// byte encodes FDS's mean of the 8 cells around it, so the mean of those cells in the slices falls inside the
// byte's interval (±0.5 of a byte); nodes on the meshes' shared face are the mean of both meshes' bytes.
TEST(FdsQuantity, SootFromSmokeFilesIsTheSlicesWithinTheBytes) {
    SmvIndex smv = readSmv(fds_test::twoMeshCase() + "/two_mesh_smoke.smv");
    FdsQuantity cells(smv, "SOOT DENSITY");
    std::erase_if(smv.files, [](const FdsFile& f) { return f.kind == FdsFile::Kind::Slice; });
    FdsQuantity nodes(smv, "SOOT DENSITY");
    EXPECT_EQ(nodes.source(), "3D smoke files");
    EXPECT_EQ(nodes.meshSourceNotes()[0], "3D smoke files (8-bit opacities)");
    const double km = 8700, dx = 0.1;
    auto byte = [&](double density) { return 254 * -std::expm1(-km * density * dx); };
    int inside = 0, checked = 0;
    for (size_t f = 1; f < nodes.times().size(); ++f) {
        Voxels c = byIndex(cells.at(cells.times()[f])), n = byIndex(nodes.at(nodes.times()[f]));
        LatticeVoxels v = nodes.at(nodes.times()[f]);
        EXPECT_EQ(v.origin, glm::dvec3(0));
        for (int k = 1; k < 10; ++k)
            for (int j = 1; j < 10; ++j)
                for (int i = 1; i < 20; ++i) {
                    if (i == 10) continue;  // the shared face: two meshes' bytes averaged
                    const double mean = cornerMean(c, i, j, k);
                    ++checked;
                    inside += std::abs(byte(n[{i, j, k}]) - byte(mean)) <= 0.5 + 1e-3;
                }
    }
    EXPECT_GT(checked, 10000);
    // All of them here; 99.34 % in the shared case's 151 frames (Smoke3dFile.SootMatchesFdsExtinctionSlice…).
    EXPECT_GE(inside, 0.98 * checked) << inside << " of " << checked;
}

// test/data/fds/slices_s16 (FDS 6.9.0, SMOKE3D_16): with its 3D slice set aside, soot comes from the 16-bit
// smoke files. Each node holds FDS's plain mean of the 8 cells around it, truncated to a step of the frame's
// range over 65535: the slice's mean of those cells lies within a step above it (a hundredth of a step for the
// floats' rounding).
TEST(FdsQuantity, SootFrom16BitSmokeFilesIsTheSlicesWithinAStep) {
    SmvIndex smv = readSmv(std::string(BRUME_TEST_DATA) + "/fds/slices_s16/slices_s16.smv");
    FdsQuantity cells(smv, "SOOT DENSITY");
    std::erase_if(smv.files, [](const FdsFile& f) { return f.kind == FdsFile::Kind::Slice; });
    FdsQuantity nodes(smv, "SOOT DENSITY");
    EXPECT_EQ(nodes.meshSourceNotes()[0], "16-bit 3D smoke files (.s16)");
    EXPECT_EQ(nodes.meshSourceNotes()[1], "16-bit 3D smoke files (.s16)");
    EXPECT_EQ(nodes.units(), "kg/m3");
    int checked = 0;
    for (double t : cells.times()) {  // the 3D slice's frames, every 2 s: the smoke files have a frame at each
        Voxels c = byIndex(cells.at(t)), n = byIndex(nodes.at(t));
        double largest = 0;
        for (const auto& [index, v] : c) largest = std::max(largest, double(v));
        const double step = largest / 65535;
        for (int k = 1; k < 10; ++k)
            for (int j = 1; j < 10; ++j)
                for (int i = 1; i < 20; ++i) {
                    const double mean = cornerMean(c, i, j, k);
                    const double node = n[{i, j, k}];
                    ASSERT_GE(mean, node - 0.01 * step - 1e-12) << t << " s, node " << i << " " << j << " " << k;
                    ASSERT_LE(mean, node + 1.01 * step + 1e-12) << t << " s, node " << i << " " << j << " " << k;
                    ++checked;
                }
    }
    EXPECT_GT(checked, 5000);
    // Temperature has no 3D slice in the case: its .s16 files, in kelvin.
    FdsQuantity temperature(readSmv(std::string(BRUME_TEST_DATA) + "/fds/slices_s16/slices_s16.smv"), "TEMPERATURE");
    EXPECT_EQ(temperature.units(), "K");
    LatticeVoxels hot = temperature.at(10);
    double most = 0;
    for (const auto& [index, v] : hot.values) most = std::max(most, double(v));
    EXPECT_GT(most, 400);  // over the burner
    EXPECT_LT(most, 2500);
}

// A layer from a horizontal slice (fds2vdb -l), in soot density whatever the slice holds: soot's extinction
// coefficient over K_m, its optical density times 2.3 over K_m (FDS's OD = K / 2.3, not K / ln 10, which is
// 0.11 % off here), its density as it is. FDS computes them from one
// another, so the same plane gives the same layer (to the floats' rounding); over the layer's heights only, the
// rest of the meshes' boxes without data.
TEST(FdsQuantity, ALayerFromAnyOfSootsSlicesIsTheSameSoot) {
    const SmvIndex all = readSmv(std::string(BRUME_TEST_DATA) + "/fds/slices_s16/slices_s16.smv");
    auto layerFrom = [&](const std::string& quantity, bool cellCentred) {
        SmvIndex smv = all;
        std::erase_if(smv.files, [&](const FdsFile& f) {
            return f.kind != FdsFile::Kind::Slice || f.quantity != quantity || f.cellCentred != cellCentred || f.volume();
        });
        FdsQuantity q(smv, "SOOT DENSITY", {5, 10}, SliceLayer{0.3, 0.8});
        EXPECT_EQ(q.meshSources()[0], MeshSource::Layer);
        EXPECT_NE(q.meshSourceNotes()[1].find("the 2D slice '" + quantity + "'"), std::string::npos) << q.meshSourceNotes()[1];
        EXPECT_EQ(q.units(), "kg/m3");
        return byIndex(q.at(10));
    };
    Voxels extinction = layerFrom("SOOT EXTINCTION COEFFICIENT", true), density = layerFrom("SOOT DENSITY", true);
    Voxels nodeExtinction = layerFrom("SOOT EXTINCTION COEFFICIENT", false),
           opticalDensity = layerFrom("SOOT OPTICAL DENSITY", false);
    ASSERT_EQ(extinction.size(), density.size());
    ASSERT_FALSE(extinction.empty());
    int k0 = 1 << 30, k1 = -k0;
    for (const auto& [index, v] : extinction) {
        EXPECT_NEAR(v, density.at(index), 1e-5 * v + 1e-12);
        k0 = std::min(k0, std::get<2>(index)), k1 = std::max(k1, std::get<2>(index));
    }
    EXPECT_EQ(k1 - k0 + 1, 5);  // the voxel centres between 0.3 and 0.8 m on the cells' lattice: 0.35 ... 0.75
    for (const auto& [index, v] : nodeExtinction) EXPECT_NEAR(v, opticalDensity.at(index), 1e-5 * v + 1e-12);
}

// With its 3D slice and smoke files set aside, the FDS 6.9.0 case's soot comes from its Plot3D files (soot's
// extinction over K_m, at 5.03 s and 10 s): each node the mean of the 8 cells around it, as the 3D slice has
// them at 10 s, to the floats' rounding.
TEST(FdsQuantity, SootFromPlot3dFilesIsTheSlicesEightCellMeans) {
    SmvIndex smv = readSmv(std::string(BRUME_TEST_DATA) + "/fds/slices_s16/slices_s16.smv");
    FdsQuantity cells(smv, "SOOT DENSITY", {10});
    std::erase_if(smv.files, [](const FdsFile& f) { return f.kind != FdsFile::Kind::Plot3d; });
    FdsQuantity nodes(smv, "SOOT DENSITY");
    EXPECT_EQ(nodes.times(), (std::vector<double>{5.03, 10}));
    EXPECT_EQ(nodes.meshSourceNotes()[1], "Plot3D files ('SOOT EXTINCTION COEFFICIENT')");
    EXPECT_EQ(nodes.units(), "kg/m3");
    Voxels c = byIndex(cells.at(10)), n = byIndex(nodes.at(10));
    int checked = 0;
    for (int k = 1; k < 10; ++k)
        for (int j = 1; j < 10; ++j)
            for (int i = 1; i < 20; ++i) {
                const double mean = cornerMean(c, i, j, k);
                const double node = n[{i, j, k}];
                ASSERT_NEAR(node, mean, 1e-5 * mean + 1e-12) << i << " " << j << " " << k;
                ++checked;
            }
    EXPECT_EQ(checked, 19 * 81);
    // Temperature is in the files too, in kelvin; an instant between them is interpolated, one beyond is refused.
    FdsQuantity temperature(smv, "TEMPERATURE", {7.5});
    EXPECT_EQ(temperature.units(), "K");
    EXPECT_THROW(FdsQuantity(smv, "TEMPERATURE", {12}), Error);
    EXPECT_THROW(readPlot3dBlock(std::string(BRUME_TEST_DATA) + "/fds/slices_s16/slices_s16_1_5p03.q", glm::ivec3(10, 10, 9), 0),
                 Error);
    EXPECT_EQ(plot3dTime("dir/case_2_10p00.q"), 10.0);
    EXPECT_EQ(plot3dTime("dir/case_2_10.q"), std::nullopt);
}

}  // namespace
}  // namespace brume
