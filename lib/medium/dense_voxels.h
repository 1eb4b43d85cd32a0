// A box of a grid's voxels copied out of its tree into one array, x fastest: a cell's 8 corners are then 8
// loads, where OpenVDB's accessor walks its tree for each (about a third of the run time of a lamp in a sphere
// of smoke at -ab 5, whose shadow rays integrate the grid cell by cell).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "medium/voxel_grid.h"

namespace brume {

class DenseVoxels {
public:
    DenseVoxels() = default;
    // The voxels of `box`, all 0.
    explicit DenseVoxels(const IndexBox& box)
        : lo_(box.lo), size_(box.hi - box.lo + 1), values_(std::size_t(size_.x) * size_.y * size_.z, 0.f) {}

    bool empty() const { return values_.empty(); }
    std::uint64_t memoryBytes() const { return values_.size() * sizeof(float); }
    // The voxel at index i, which must be in the box.
    float& at(const glm::ivec3& i) { return values_[offset(i - lo_)]; }
    // The voxel at index i, 0 outside the box.
    float value(const glm::ivec3& i) const {
        const glm::ivec3 d = i - lo_;
        return inside(d, size_) ? values_[offset(d)] : 0.f;
    }
    // The 8 voxels at the corners of the cell whose lowest corner is `cell`, as VoxelGrid::cellCorners orders them.
    void cellCorners(const glm::ivec3& cell, float* corners) const {
        const glm::ivec3 d = cell - lo_;
        if (!inside(d, size_ - 1)) {
            for (int k = 0; k < 8; ++k) corners[k] = value(cell + glm::ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
            return;
        }
        const std::size_t o = offset(d), dy = std::size_t(size_.x), dz = dy * std::size_t(size_.y);
        const float* v = values_.data();
        corners[0] = v[o], corners[1] = v[o + 1], corners[2] = v[o + dy], corners[3] = v[o + dy + 1];
        corners[4] = v[o + dz], corners[5] = v[o + dz + 1], corners[6] = v[o + dz + dy], corners[7] = v[o + dz + dy + 1];
    }

private:
    static bool inside(const glm::ivec3& d, const glm::ivec3& size) {
        return d.x >= 0 && d.y >= 0 && d.z >= 0 && d.x < size.x && d.y < size.y && d.z < size.z;
    }
    std::size_t offset(const glm::ivec3& d) const {
        return (std::size_t(d.z) * std::size_t(size_.y) + std::size_t(d.y)) * std::size_t(size_.x) + std::size_t(d.x);
    }

    glm::ivec3 lo_{0}, size_{0};
    std::vector<float> values_;
};

}  // namespace brume
