#include "geometry/scene_geometry.h"

#include <cmath>
#include <limits>

#include "geometry/polygon.h"

namespace brume {

namespace {

// Embree's per-query context, extended with the exact ray and the exact hit of our own shapes.
struct TraceContext {
    RTCIntersectContext rtc;
    const SceneGeometry* geometry;
    const std::vector<int>* triangleSurface;
    const Ray* ray;
    double exactT;
    dvec3 exactNormal;
};

// Axis-aligned half extent of a disk of radius r whose plane has unit normal n.
dvec3 diskExtent(const dvec3& n, double r) {
    return r * glm::sqrt(glm::max(dvec3(0), dvec3(1) - n * n));
}

void shapeBounds(const Shape& shape, dvec3& lo, dvec3& hi) {
    struct {
        dvec3 &lo, &hi;
        void operator()(const Sphere& s) { lo = s.center - s.radius, hi = s.center + s.radius; }
        void operator()(const Cone& c) {
            dvec3 a = glm::normalize(c.top - c.base);
            dvec3 e0 = diskExtent(a, c.baseRadius), e1 = diskExtent(a, c.topRadius);
            lo = glm::min(c.base - e0, c.top - e1), hi = glm::max(c.base + e0, c.top + e1);
        }
        void operator()(const Ring& r) {
            dvec3 e = diskExtent(r.normal, r.outerRadius);
            lo = r.center - e, hi = r.center + e;
        }
        void operator()(const Polygon& p) {
            lo = hi = p.vertices[0];
            for (const dvec3& v : p.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
        }
    } visit{lo, hi};
    std::visit(visit, shape);
}

void skipLeavingTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<const TraceContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if ((*ctx->triangleSurface)[prim] == ctx->ray->leaving) args->valid[i] = 0;
    }
}

}  // namespace

SceneGeometry::SceneGeometry(std::vector<Surface> surfaces) : surfaces_(std::move(surfaces)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("cannot create Embree device");
    scene_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    lo_ = dvec3(std::numeric_limits<double>::infinity());
    hi_ = -lo_;
    for (const Surface& s : surfaces_) {
        dvec3 lo, hi;
        shapeBounds(s.shape, lo, hi);
        lo_ = glm::min(lo_, lo), hi_ = glm::max(hi_, hi);
    }
    addTriangles();
    addExactShapes();
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw Error("Embree failed to build the scene");
}

SceneGeometry::~SceneGeometry() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

void SceneGeometry::addTriangles() {
    std::vector<float> vertices;
    std::vector<unsigned> indices;
    for (int s = 0; s < static_cast<int>(surfaces_.size()); ++s) {
        const auto* poly = std::get_if<Polygon>(&surfaces_[s].shape);
        if (!poly) continue;
        unsigned first = static_cast<unsigned>(vertices.size() / 3);
        for (const dvec3& v : poly->vertices)
            for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<float>(v[k]));
        for (const auto& t : poly->triangles) {
            for (int k = 0; k < 3; ++k) indices.push_back(first + t[k]);
            triangleSurface_.push_back(s);
        }
    }
    if (indices.empty()) return;
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), vertices.size() / 3));
    std::copy(vertices.begin(), vertices.end(), vb);
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), indices.size() / 3));
    std::copy(indices.begin(), indices.end(), ib);
    rtcSetGeometryIntersectFilterFunction(geom, skipLeavingTriangle);
    rtcCommitGeometry(geom);
    triangleGeom_ = rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
}

void SceneGeometry::addExactShapes() {
    for (int s = 0; s < static_cast<int>(surfaces_.size()); ++s)
        if (!std::holds_alternative<Polygon>(surfaces_[s].shape)) exactSurface_.push_back(s);
    if (exactSurface_.empty()) return;
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(exactSurface_.size()));
    rtcSetGeometryUserData(geom, this);
    rtcSetGeometryBoundsFunction(geom, exactBounds, this);
    rtcSetGeometryIntersectFunction(geom, exactIntersect);
    rtcCommitGeometry(geom);
    exactGeom_ = rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
}

void SceneGeometry::exactBounds(const RTCBoundsFunctionArguments* args) {
    auto* self = static_cast<const SceneGeometry*>(args->geometryUserPtr);
    dvec3 lo, hi;
    shapeBounds(self->surfaces_[self->exactSurface_[args->primID]].shape, lo, hi);
    // Widen by a relative margin so float rounding of the box never clips the exact shape.
    dvec3 pad = 1e-6 * (glm::abs(lo) + glm::abs(hi) + (hi - lo)) + 1e-30;
    lo -= pad, hi += pad;
    *args->bounds_o = RTCBounds{float(lo.x), float(lo.y), float(lo.z), 0, float(hi.x), float(hi.y), float(hi.z), 0};
}

void SceneGeometry::exactIntersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* self = static_cast<const SceneGeometry*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);  // rtcIntersect1 only: N is 1
    int s = self->exactSurface_[args->primID];
    Ray ray = *ctx->ray;
    ray.tmax = std::min(ray.tmax, static_cast<double>(rayhit->ray.tfar));
    std::optional<ShapeHit> hit = std::visit(
        [&](const auto& shape) -> std::optional<ShapeHit> {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, Ring>) {
                if (s == ray.leaving) return std::nullopt;
                return shape.intersect(ray);
            } else if constexpr (std::is_same_v<T, Polygon>) {
                return std::nullopt;
            } else {
                return shape.intersect(ray, s == ray.leaving);
            }
        },
        self->surfaces_[s].shape);
    if (!hit) return;
    rayhit->ray.tfar = static_cast<float>(hit->t);
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.instID[0] = args->context->instID[0];
    ctx->exactT = hit->t;
    ctx->exactNormal = hit->normal;
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.geometry = this;
    ctx.triangleSurface = &triangleSurface_;
    ctx.ray = &ray;
    RTCRayHit rh{};
    rh.ray.org_x = float(ray.org.x), rh.ray.org_y = float(ray.org.y), rh.ray.org_z = float(ray.org.z);
    rh.ray.dir_x = float(ray.dir.x), rh.ray.dir_y = float(ray.dir.y), rh.ray.dir_z = float(ray.dir.z);
    rh.ray.tnear = float(ray.tmin);
    rh.ray.tfar = ray.tmax > 3e38 ? std::numeric_limits<float>::infinity() : float(ray.tmax);
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    // Embree traces rays only within ±1.8e18 (its FLT_LARGE); farther ones meet nothing.
    for (float v : {rh.ray.org_x, rh.ray.org_y, rh.ray.org_z, rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z, rh.ray.tnear})
        if (!(std::abs(v) <= 1.8e18f)) return std::nullopt;
    rtcIntersect1(scene_, &ctx.rtc, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (rh.hit.geomID == exactGeom_) {
        int s = exactSurface_[rh.hit.primID];
        return SurfaceHit{ctx.exactT, ray.at(ctx.exactT), ctx.exactNormal, s};
    }
    int s = triangleSurface_[rh.hit.primID];
    const auto& poly = std::get<Polygon>(surfaces_[s].shape);
    // The exact distance to the plane; Embree's float t only chose the triangle.
    double t = poly.planeDistance(ray);
    if (!(t > 0) || !std::isfinite(t)) t = rh.ray.tfar;
    return SurfaceHit{t, ray.at(t), poly.normal, s};
}

}  // namespace brume
