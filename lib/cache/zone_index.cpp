#include "cache/zone_index.h"

#include <embree3/rtcore.h>

namespace brume {

struct ZoneIndex::Embree {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = nullptr;
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

ZoneIndex::ZoneIndex() : embree_(std::make_unique<Embree>()) {}

ZoneIndex::~ZoneIndex() = default;

void ZoneIndex::build(const std::vector<ZoneBox>& boxes) {
    if (embree_->scene) rtcReleaseScene(embree_->scene);
    embree_->scene = rtcNewScene(embree_->device);
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(boxes.size()));
    rtcSetGeometryUserData(geometry, const_cast<ZoneBox*>(boxes.data()));
    rtcSetGeometryBoundsFunction(
        geometry,
        [](const RTCBoundsFunctionArguments* args) {
            const ZoneBox& b = static_cast<const ZoneBox*>(args->geometryUserPtr)[args->primID];
            args->bounds_o->lower_x = b.lo[0], args->bounds_o->upper_x = b.hi[0];
            args->bounds_o->lower_y = b.lo[1], args->bounds_o->upper_y = b.hi[1];
            args->bounds_o->lower_z = b.lo[2], args->bounds_o->upper_z = b.hi[2];
        },
        nullptr);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(embree_->scene);  // the boxes are read here, and not after
    size_ = boxes.size();
}

namespace {
struct Found {
    void* f;
    void (*call)(void*, size_t);
};
}  // namespace

void ZoneIndex::query(const glm::dvec3& q, void (*call)(void*, size_t), void* f) const {
    Found found{f, call};
    RTCPointQuery query;
    query.x = float(q.x), query.y = float(q.y), query.z = float(q.z);
    query.time = 0, query.radius = 0;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(embree_->scene, &query, &context,
                  [](RTCPointQueryFunctionArguments* args) {
                      auto* found = static_cast<Found*>(args->userPtr);
                      found->call(found->f, args->primID);
                      return false;
                  },
                  &found);
}

}  // namespace brume
