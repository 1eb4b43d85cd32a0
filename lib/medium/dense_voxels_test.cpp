#include "medium/dense_voxels.h"

#include <gtest/gtest.h>

#include <cmath>

#include "medium/testing.h"
#include "sampling/random.h"

namespace brume {
namespace {

using namespace medium::testing;

// A sparse grid with a tile (the 8³ block 16..23 filled at once), scattered voxels and gaps between them, with
// a voxel size and offset that are not 1 and 0.
openvdb::FloatGrid::Ptr scatteredGrid() {
    auto grid = boxGrid(openvdb::Coord(16), openvdb::Coord(23), 0.5f, 0.1);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(0.1));
    grid->transform().postTranslate(openvdb::Vec3d(0.3, -0.2, 1.1));
    Random random(5, 5);
    auto voxels = grid->getAccessor();
    for (int i = 0; i < 3000; ++i) {
        openvdb::Coord c(int(random.uniform() * 40) - 10, int(random.uniform() * 40) - 10, int(random.uniform() * 40) - 10);
        voxels.setValue(c, float(random.uniform() * 3));
    }
    return grid;
}

// The copy gives every cell's corners and every density the tree gives: inside the box, at its faces, beyond it.
TEST(DenseVoxels, TheCopyReadsAsTheTree) {
    std::vector<std::string> warnings;
    OpenVdbGrid copied(scatteredGrid(), "copied", warnings), tree(scatteredGrid(), "tree", warnings, OpenVdbGrid::Copy::Never);
    ASSERT_GT(copied.memoryBytes(), tree.memoryBytes());  // the copy was made
    std::vector<glm::ivec3> cells;
    for (int x = -13; x <= 32; ++x)
        for (int y = -13; y <= 32; y += 3)
            for (int z = -13; z <= 32; z += 5) cells.emplace_back(x, y, z);
    std::vector<float> a(8 * cells.size()), b(8 * cells.size());
    copied.cellCorners(cells, a);
    tree.cellCorners(cells, b);
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "cell " << i / 8 << " corner " << i % 8;
    Random random(9, 9);
    for (int i = 0; i < 20000; ++i) {
        dvec3 p = dvec3(0.3, -0.2, 1.1) + 0.1 * dvec3(random.uniform(), random.uniform(), random.uniform()) * 46.0 - 1.3;
        double t = tree.density(p);
        ASSERT_NEAR(copied.density(p), t, 1e-6 * (1 + t)) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_EQ(copied.density(dvec3(1e30, 0, 0)), 0);
}

// A box mostly empty is not copied: here 2001 x 2001 x 2 voxels (32 MB) for five.
TEST(DenseVoxels, ASparseBoxIsNotCopied) {
    std::vector<std::string> warnings;
    auto grid = boxGrid(openvdb::Coord(0), openvdb::Coord(1), 1.f);
    grid->tree().setValue(openvdb::Coord(2000, 0, 0), 1.f);
    grid->tree().setValue(openvdb::Coord(0, 2000, 0), 1.f);
    OpenVdbGrid sparse(grid, "sparse", warnings);
    EXPECT_LT(sparse.memoryBytes(), 1u << 20);
}

}  // namespace
}  // namespace brume
