#include "medium/openvdb/openvdb_grid.h"

#include <openvdb/io/File.h>
#include <openvdb/tools/Interpolation.h>

#include <cmath>
#include <sstream>

#include "util/error.h"

namespace brume {

namespace {
IndexBox indexBox(const openvdb::CoordBBox& b) {
    return {glm::ivec3(b.min().x(), b.min().y(), b.min().z()), glm::ivec3(b.max().x(), b.max().y(), b.max().z())};
}
}  // namespace

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

namespace {
// The active voxels of `grid` in the box `b`, the rest 0.
DenseVoxels denseCopy(const openvdb::FloatGrid& grid, const openvdb::CoordBBox& b) {
    DenseVoxels dense(indexBox(b));
    openvdb::CoordBBox box;
    for (auto it = grid.tree().cbeginValueOn(); it; ++it) {
        if (!it.getBoundingBox(box)) continue;
        const float v = *it;
        for (auto c = box.begin(); c; ++c) dense.at(glm::ivec3((*c).x(), (*c).y(), (*c).z())) = v;
    }
    return dense;
}
}  // namespace

OpenVdbGrid::OpenVdbGrid(openvdb::FloatGrid::Ptr vdb, std::string source, std::vector<std::string>& warnings,
                         Copy copy) {
    if (vdb->getGridClass() == openvdb::GRID_LEVEL_SET) throw Error(source + " is a level set, not a density");
    if (!vdb->transform().isLinear())
        throw Error(source + " has a frustum (non-linear) transform; only linear ones are read");
    openvdb::FloatTree& tree = vdb->tree();
    if (tree.background() != 0)
        warnings.push_back(source + " has background " + (std::ostringstream() << tree.background()).str() +
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
            max_ = std::max(max_, v);
        }
    }
    if (hostile) warnings.push_back(source + ": " + std::to_string(hostile) + " NaN, infinite or negative voxels read as 0");
    active_ = vdb->evalActiveVoxelBoundingBox();
    if (copy == Copy::WhenSmall && !active_.empty() &&
        double(active_.volume()) * sizeof(float) <= 2.0 * double(vdb->memUsage()))
        dense_ = denseCopy(*vdb, active_);
    grid_ = std::move(vdb);
}

Bounds3 OpenVdbGrid::bounds() const {
    Bounds3 b;
    if (active_.empty()) return b;
    openvdb::Vec3d lo = active_.min().asVec3d() - 1.0, hi = active_.max().asVec3d() + 1.0;
    for (int corner = 0; corner < 8; ++corner) {
        openvdb::Vec3d p = grid_->indexToWorld(
            openvdb::Vec3d(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z()));
        b.include(dvec3(p.x(), p.y(), p.z()));
    }
    return b;
}

double OpenVdbGrid::density(const dvec3& p) const {
    if (!dense_.empty()) {
        const openvdb::Vec3d x = grid_->worldToIndex(openvdb::Vec3d(p.x, p.y, p.z));
        for (int a = 0; a < 3; ++a)  // no smoke a voxel or more outside the box (nor int overflow far away)
            if (!(x[a] > active_.min()[a] - 1 && x[a] < active_.max()[a] + 1)) return 0;
        const openvdb::Vec3d lo(std::floor(x.x()), std::floor(x.y()), std::floor(x.z())), f = x - lo;
        float c[8];
        dense_.cellCorners(glm::ivec3(int(lo.x()), int(lo.y()), int(lo.z())), c);
        auto mix = [](double a, double b, double t) { return a + t * (b - a); };
        return mix(mix(mix(c[0], c[1], f.x()), mix(c[2], c[3], f.x()), f.y()),
                   mix(mix(c[4], c[5], f.x()), mix(c[6], c[7], f.x()), f.y()), f.z());
    }
    // An unsafe accessor does not register with the tree (a locked table): cheap to make per lookup, and
    // the tree never changes after load.
    auto voxels = grid_->getConstUnsafeAccessor();
    return openvdb::tools::BoxSampler::sample(voxels, grid_->worldToIndex(openvdb::Vec3d(p.x, p.y, p.z)));
}

// OpenVDB's matrices act on row vectors: transposed into one on column vectors.
glm::dmat4 OpenVdbGrid::worldFromIndex() const {
    const openvdb::Mat4d m = grid_->transform().baseMap()->getAffineMap()->getMat4();
    glm::dmat4 g;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g[i][j] = m[i][j];
    return g;
}

bool OpenVdbGrid::sameTransform(const VoxelGrid& other) const {
    const auto* o = dynamic_cast<const OpenVdbGrid*>(&other);
    return o && o->grid_->transform() == grid_->transform();
}

std::optional<IndexBox> OpenVdbGrid::activeBox() const {
    if (active_.empty()) return std::nullopt;
    return indexBox(active_);
}

void OpenVdbGrid::forEachActive(const std::function<void(const IndexBox&, float)>& visit) const {
    openvdb::CoordBBox box;
    for (auto it = grid_->tree().cbeginValueOn(); it; ++it) {
        const float v = *it;
        if (v > 0 && it.getBoundingBox(box)) visit(indexBox(box), v);
    }
}

float OpenVdbGrid::minimum(const IndexBox& box) const {
    auto accessor = grid_->getConstAccessor();
    const openvdb::CoordBBox b(openvdb::Coord(box.lo.x, box.lo.y, box.lo.z), openvdb::Coord(box.hi.x, box.hi.y, box.hi.z));
    float m = std::numeric_limits<float>::infinity();
    for (auto c = b.begin(); c && m > 0; ++c) {
        float v;
        m = accessor.probeValue(*c, v) ? std::min(m, v) : 0.0f;
    }
    return std::max(0.0f, m);
}

// From the copy where there is one; else one accessor for the whole batch: consecutive cells along a ray share
// the tree's nodes it caches, and, one step apart along an axis, the four corners of the face between them.
void OpenVdbGrid::cellCorners(std::span<const glm::ivec3> cells, std::span<float> corners) const {
    if (!dense_.empty()) {
        for (std::size_t n = 0; n < cells.size(); ++n) dense_.cellCorners(cells[n], &corners[8 * n]);
        return;
    }
    auto accessor = grid_->getConstUnsafeAccessor();
    for (std::size_t n = 0; n < cells.size(); ++n) {
        float* c = &corners[8 * n];
        glm::ivec3 step = n > 0 ? cells[n] - cells[n - 1] : glm::ivec3(0);
        int axis = -1;
        if (std::abs(step.x) + std::abs(step.y) + std::abs(step.z) == 1) axis = step.x ? 0 : step.y ? 1 : 2;
        for (int k = 0; k < 8; ++k) {
            const int bit = axis < 0 ? 0 : (k >> axis) & 1;
            // Corner k of this cell is the previous cell's corner with the axis bit flipped, where they share it.
            if (axis >= 0 && bit == (step[axis] > 0 ? 0 : 1)) {
                c[k] = corners[8 * (n - 1) + (k ^ (1 << axis))];
                continue;
            }
            c[k] = accessor.getValue(openvdb::Coord(cells[n].x + (k & 1), cells[n].y + ((k >> 1) & 1), cells[n].z + ((k >> 2) & 1)));
        }
    }
}

std::string OpenVdbGrid::metadata(const std::string& key) const {
    auto text = grid_->getMetadata<openvdb::StringMetadata>(key);
    return text ? text->value() : std::string();
}

}  // namespace brume
