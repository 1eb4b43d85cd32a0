// Embree's BVH over the boxes that hold records' zones, asked with point queries: which boxes hold a point.
// Boxes are floats measured from an origin (the scene's), so that they stay precise at a site's coordinates.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

struct ZoneBox {
    float lo[3], hi[3];
};

class ZoneIndex {
public:
    ZoneIndex();
    ~ZoneIndex();
    ZoneIndex(const ZoneIndex&) = delete;
    ZoneIndex& operator=(const ZoneIndex&) = delete;

    // Indexes these boxes (numbered by their place), in place of those indexed before.
    void build(const std::vector<ZoneBox>& boxes);
    // How many boxes the last build indexed.
    size_t size() const { return size_; }
    // Calls f(i) for each indexed box i that holds `q` (measured from the boxes' origin).
    template <class F>
    void forEachHolding(const glm::dvec3& q, F&& f) const {
        if (size_ == 0) return;
        query(q, [](void* g, size_t i) { (*static_cast<std::remove_reference_t<F>*>(g))(i); }, &f);
    }

private:
    void query(const glm::dvec3& q, void (*call)(void*, size_t), void* f) const;
    struct Embree;
    std::unique_ptr<Embree> embree_;
    size_t size_ = 0;
};

}  // namespace brume
