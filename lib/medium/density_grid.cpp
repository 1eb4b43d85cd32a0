#include "medium/density_grid.h"

#include <openvdb/io/File.h>
#include <openvdb/tools/Interpolation.h>

#include <cmath>
#include <sstream>

#include "medium/density_grid_vdb.h"
#include "util/error.h"

namespace brume {

namespace {

openvdb::FloatGrid::Ptr readFloatGrid(const std::string& path, const std::string& name) {
    openvdb::initialize();
    openvdb::GridBase::Ptr grid;
    try {
        openvdb::io::File file(path);
        file.open(/*delayLoad=*/false);  // every voxel is read anyway, to be cleaned
        if (!file.hasGrid(name)) {
            std::string names;
            for (auto it = file.beginName(); it != file.endName(); ++it)
                names += (names.empty() ? "\"" : ", \"") + it.gridName() + "\"";
            throw Error(path + ": no grid \"" + name + "\" (" +
                        (names.empty() ? "the file holds no grid" : "the file holds " + names) + ")");
        }
        grid = file.readGrid(name);
    } catch (const openvdb::Exception& e) {
        throw Error(path + ": " + e.what());
    }
    auto floats = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
    if (!floats)
        throw Error(path + ": grid \"" + name + "\" holds " + grid->valueType() + " values, not float densities");
    return floats;
}

}  // namespace

DensityGrid::Voxels::Voxels(openvdb::FloatGrid::Ptr vdb, std::string name) : source(std::move(name)) {
    if (vdb->getGridClass() == openvdb::GRID_LEVEL_SET) throw Error(source + " is a level set, not a density");
    if (!vdb->transform().isLinear())
        throw Error(source + " has a frustum (non-linear) transform; only linear ones are read");
    openvdb::FloatTree& tree = vdb->tree();
    if (tree.background() != 0)
        warn(source + " has background " + (std::ostringstream() << tree.background()).str() +
             ": read as 0 (the smoke is its active voxels)");
    tree.root().setBackground(0.0f, /*updateChildNodes=*/false);
    // One pass over every stored value, tiles once each: the tree stays as sparse as in the file.
    std::uint64_t hostile = 0;
    for (auto it = tree.beginValueAll(); it; ++it) {
        float v = *it;
        if (!it.isValueOn()) {
            if (v != 0) it.setValue(0.0f);
        } else if (!(v >= 0) || std::isinf(v)) {
            it.setValue(0.0f);
            hostile += it.getVoxelCount();
        } else {
            max = std::max(max, v);
        }
    }
    if (hostile)
        warn(source + ": " + std::to_string(hostile) + " NaN, infinite or negative voxels read as 0");
    active = vdb->evalActiveVoxelBoundingBox();
    grid = std::move(vdb);
}

DensityGrid::DensityGrid(const std::string& path, const std::string& name)
    : voxels_(std::make_shared<Voxels>(readFloatGrid(path, name), path + ": grid \"" + name + "\"")) {}

Bounds3 DensityGrid::bounds() const {
    Bounds3 b;
    if (voxels_->active.empty()) return b;
    openvdb::Vec3d lo = voxels_->active.min().asVec3d() - 1.0, hi = voxels_->active.max().asVec3d() + 1.0;
    for (int corner = 0; corner < 8; ++corner) {
        openvdb::Vec3d p = voxels_->grid->indexToWorld(
            openvdb::Vec3d(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z()));
        b.include(dvec3(p.x(), p.y(), p.z()));
    }
    return b;
}

double DensityGrid::density(const dvec3& p) const {
    const openvdb::FloatGrid& grid = *voxels_->grid;
    // An unsafe accessor does not register with the tree (a locked table): cheap to make per lookup, and
    // the tree never changes after load.
    auto voxels = grid.getConstUnsafeAccessor();
    return openvdb::tools::BoxSampler::sample(voxels, grid.worldToIndex(openvdb::Vec3d(p.x, p.y, p.z)));
}

double DensityGrid::maxDensity() const { return voxels_->max; }

std::uint64_t DensityGrid::activeVoxelCount() const { return voxels_->grid->activeVoxelCount(); }

std::uint64_t DensityGrid::memoryBytes() const { return voxels_->grid->memUsage(); }

}  // namespace brume
