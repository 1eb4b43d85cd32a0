// fds2vdb end to end: the grids it writes hold the imported values where FdsQuantity puts them, the same as the
// shared data's hand-converted grids, and the smoke object it prints renders.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdio>

#include "cli.h"
#include "fds/fds_quantity.h"
#include "fds/testing.h"
#include "scratch_dir.h"

namespace {

using brume_test::Output;

openvdb::FloatGrid::Ptr readGrid(const std::string& path, const std::string& name) {
    openvdb::initialize();
    openvdb::io::File file(path);
    file.open();
    auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
    file.close();
    return grid;
}

TEST(Fds2vdb, WritesTheImportedValuesAndASmokeObjectThatRenders) {
    auto dir = brume_test::scratchDir("fds2vdb");
    const std::string smv = brume::fds_test::twoMeshCase() + "/two_mesh_smoke.smv";
    Output r = brume_test::runBrume("fds2vdb -f -t 10,11 '" + smv + "' > smoke.rad", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    std::string rad = brume_test::slurp(dir / "smoke.rad");
    EXPECT_NE(rad.find("void smoke two_mesh_smoke_soot_density\n6 temperature=temperature extinction=soot 10 "
                       "two_mesh_smoke_soot_density_0010.000.vdb 11 two_mesh_smoke_soot_density_0011.000.vdb\n"),
              std::string::npos)
        << rad;
    EXPECT_NE(rad.find("7 8700 8700 8700"), std::string::npos) << rad;
    brume::SmvIndex index = brume::readSmv(smv);
    for (const char* name : {"density", "temperature"}) {
        brume::FdsQuantity q(index, name == std::string("density") ? "SOOT DENSITY" : "TEMPERATURE");
        brume::LatticeVoxels v = q.at(11);
        auto grid = readGrid((dir / "two_mesh_smoke_soot_density_0011.000.vdb").string(), name);
        ASSERT_TRUE(grid) << name;
        EXPECT_EQ(grid->activeVoxelCount(), v.values.size()) << name;
        auto access = grid->getConstAccessor();
        for (const auto& [i, value] : v.values) {
            openvdb::Coord c(i.x, i.y, i.z);
            ASSERT_EQ(access.getValue(c), value) << name;
            glm::dvec3 centre = v.origin + glm::dvec3(i) * v.spacing;
            ASSERT_NEAR((grid->indexToWorld(c) - openvdb::Vec3d(centre.x, centre.y, centre.z)).length(), 0, 1e-9);
        }
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "two_mesh_smoke_soot_density_0011.000.vdb.part"));
    // The object renders: a ray along the room's length through the smoke at 20 s, toward a white glow. The smoke
    // scatters only a fifth, and -ab 0 with no light source leaves only what it lets through.
    std::ofstream(dir / "wall.rad") << "void glow white 0 0 4 1 1 1 0\nwhite polygon far 0 0 12 3 -1 -1 3 2 -1 3 2 2 3 -1 2\n";
    Output trace = brume_test::runBrume("echo '-1 0.5 0.95 1 0 0' | rtrace -h -ab 0 -ov -T 10 wall.rad smoke.rad", dir);
    ASSERT_EQ(trace.status, 0) << trace.err;
    double red = std::stod(trace.out);
    EXPECT_LT(red, 0.9) << trace.out;  // the ceiling's smoke at 10-11 s, 2 m of it
    EXPECT_GT(red, 0.0) << trace.out;
    // Without -T the run is at 0 s, before the case's frames: an error naming them, and no output.
    Output before = brume_test::runBrume("echo '-1 0.5 0.95 1 0 0' | rtrace -h -ab 0 -ov wall.rad smoke.rad", dir);
    EXPECT_NE(before.status, 0);
    EXPECT_EQ(before.out, "");
    EXPECT_NE(before.err.find("smoke.rad:"), std::string::npos) << before.err;
    EXPECT_NE(before.err.find("no data at 0 s, outside its 2 key frames (10 to 11 s"), std::string::npos) << before.err;
    // -g: soot's 633 nm K in every band, as before soot's spectrum was written.
    Output grey = brume_test::runBrume("fds2vdb -g -t 10 '" + smv + "'", dir);
    ASSERT_EQ(grey.status, 0) << grey.err;
    EXPECT_NE(grey.out.find("void smoke two_mesh_smoke_soot_density\n1 two_mesh_smoke_soot_density_0010.000.vdb\n"),
              std::string::npos)
        << grey.out;
}

TEST(Fds2vdb, GivesTheSharedDataHandConvertedGrids) {
    const std::string dir = brume::fds_test::sharedCase();
    if (dir.empty()) GTEST_SKIP() << "no ../shared/data";
    const std::string shared = std::string(BRUME_SHARED_DATA) + "/vdb/fds_room_fire_mesh2_soot/soot_t120.vdb";
    auto theirs = readGrid(shared, "density");
    // Their metadata rounds the frame's time to a millisecond: the frame nearest it, to the last digit.
    const double rounded = std::stod((*theirs)["fds_time_s"]->str());
    const std::string smv = dir + "/model.smv";
    std::vector<double> around = brume::FdsQuantity(brume::readSmv(smv), "SOOT DENSITY", {rounded}).times();
    char time[32];
    std::snprintf(time, sizeof time, "%.17g", *std::min_element(around.begin(), around.end(), [&](double a, double b) {
        return std::abs(a - rounded) < std::abs(b - rounded);
    }));
    auto scratch = brume_test::scratchDir("fds2vdb_shared");
    Output r = brume_test::runBrume("fds2vdb -t " + std::string(time) + " -o soot '" + smv + "' > smoke.rad", scratch);
    ASSERT_EQ(r.status, 0) << r.err;
    // Only mesh 2 has its 3D smoke file in the shared data: the others are named, not silently left out.
    EXPECT_NE(r.err.find("mesh 1 (") , std::string::npos) << r.err;
    std::vector<std::filesystem::path> written;
    for (const auto& e : std::filesystem::directory_iterator(scratch))
        if (e.path().extension() == ".vdb") written.push_back(e.path());
    ASSERT_EQ(written.size(), 1u);
    auto ours = readGrid(written[0].string(), "density");
    EXPECT_EQ(ours->activeVoxelCount(), theirs->activeVoxelCount());
    auto mine = ours->getConstAccessor();
    double worst = 0;
    for (auto v = theirs->cbeginValueOn(); v; ++v) {
        openvdb::Vec3d world = theirs->indexToWorld(v.getCoord());
        openvdb::Coord c = openvdb::Coord::round(ours->worldToIndex(world));
        worst = std::max(worst, std::abs(double(mine.getValue(c)) - double(*v)) / double(*v));
    }
    EXPECT_LT(worst, 1e-6);  // the same formula, in floats
}

TEST(Fds2vdb, RefusesInstantsOutsideTheFramesBeforeWritingAnything) {
    auto dir = brume_test::scratchDir("fds2vdb_refuse");
    const std::string smv = brume::fds_test::twoMeshCase() + "/two_mesh_smoke.smv";
    Output r = brume_test::runBrume("fds2vdb -t 10,30 '" + smv + "'", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("fds2vdb: " + brume::fds_test::twoMeshCase() + "/two_mesh_smoke_1_1.sf: no frame around 30 s: the file holds 0 s to 20"), std::string::npos)
        << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir) || !std::filesystem::exists(dir / "two_mesh_smoke_soot_density_0010.000.vdb"));
    Output usage = brume_test::runBrume("fds2vdb -t 20,10 '" + smv + "'", dir);
    EXPECT_NE(usage.status, 0);
    EXPECT_NE(usage.err.find("-t: instants must increase"), std::string::npos) << usage.err;
    Output missing = brume_test::runBrume("fds2vdb nowhere.smv", dir);
    EXPECT_EQ(missing.status, 1);
    EXPECT_EQ(missing.err.rfind("fds2vdb: nowhere.smv", 0), 0u) << missing.err;
    for (const char* layer : {"2,1", "1", "1,x"}) {
        Output bad = brume_test::runBrume("fds2vdb -l " + std::string(layer) + " '" + smv + "'", dir);
        EXPECT_NE(bad.status, 0) << layer;
        EXPECT_EQ(bad.out, "") << layer;
        EXPECT_NE(bad.err.find("-l"), std::string::npos) << bad.err;
    }
}

}  // namespace
