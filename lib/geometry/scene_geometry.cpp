#include "geometry/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <glm/gtx/component_wise.hpp>
#include <limits>

#include "geometry/polygon.h"

namespace brume {

namespace {

// Embree geometry IDs: in every group's scene, its triangles and its exact shapes; in the world's, the
// placements after them (placement p is ID kFirstPlacementGeom + p).
constexpr unsigned kTrianglesGeom = 0, kExactGeom = 1, kFirstPlacementGeom = 2;

// Embree's per-query context, extended with the exact ray and the exact hit of our own shapes.
struct TraceContext {
    RTCIntersectContext rtc;
    const SceneGeometry* geometry;
    const Ray* ray;  // in world coordinates
    double exactT;
    dvec3 exactNormal;  // in the coordinates of the shape's prototype
};

int placementOf(unsigned instID) { return instID == RTC_INVALID_GEOMETRY_ID ? -1 : int(instID - kFirstPlacementGeom); }

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

// Meshes, where the memory goes, get Embree's compact structures: a fifth less memory for a 1M-triangle mesh,
// no measurable loss of speed.
RTCScene newScene(RTCDevice device, bool compact) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, compact ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT : RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    return scene;
}

// A triangle geometry with a float copy of `vertices` and the given index buffer.
RTCGeometry newTriangles(RTCDevice device, const std::vector<dvec3>& vertices, const unsigned* indices, size_t count,
                         bool shareIndices) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
    for (size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vb[3 * i + k] = static_cast<float>(vertices[i][k]);
    if (shareIndices) {
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0, 3 * sizeof(unsigned), count);
    } else {
        auto* ib = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
        std::copy(indices, indices + 3 * count, ib);
    }
    return geom;
}

SceneLayout ownSurfacesOnly(std::vector<Surface> surfaces) {
    int n = int(surfaces.size());
    return SceneLayout{std::move(surfaces), n, {}, {}};
}

void attach(RTCScene scene, RTCGeometry geom, unsigned id) {
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene, geom, id);
    rtcReleaseGeometry(geom);
}

}  // namespace

// One Embree scene: the scene's own surfaces, or one prototype's.
struct SceneGeometry::Group {
    const SceneGeometry* owner = nullptr;
    RTCScene scene = nullptr;
    int firstSurface = 0, endSurface = 0;
    const Mesh* mesh = nullptr;          // a mesh prototype: triangle primIDs are the mesh's triangles
    std::vector<int> triangleSurface;    // polygon triangle primID → surface
    std::vector<int> exactSurface;       // user-geometry primID → surface
    dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};

    SurfaceId idOf(unsigned geomID, unsigned primID, int placement) const {
        if (geomID == kExactGeom) return {exactSurface[primID], placement, -1};
        if (mesh) return {-1, placement, int(primID)};
        return {triangleSurface[primID], placement, -1};
    }
};

SceneGeometry::SceneGeometry(std::vector<Surface> surfaces) : SceneGeometry(ownSurfacesOnly(std::move(surfaces))) {}

SceneGeometry::SceneGeometry(SceneLayout layout) : layout_(std::move(layout)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("cannot create Embree device");
    groups_.resize(1 + layout_.prototypes.size());
    for (size_t k = 0; k < layout_.prototypes.size(); ++k) buildGroup(groups_[1 + k], int(k));
    buildGroup(groups_[0], -1);
    computeBounds();
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw Error("Embree failed to build the scene");
}

SceneGeometry::~SceneGeometry() {
    for (Group& g : groups_)
        if (g.scene) rtcReleaseScene(g.scene);
    if (device_) rtcReleaseDevice(device_);
}

// Prototype k's group, or with k = -1 the world's (its own surfaces and the placements).
void SceneGeometry::buildGroup(Group& g, int k) {
    g.owner = this;
    g.endSurface = layout_.ownSurfaces;
    if (k >= 0) {
        const Prototype& p = layout_.prototypes[k];
        g.firstSurface = p.firstSurface, g.endSurface = p.endSurface, g.mesh = p.mesh;
    }
    g.scene = newScene(device_, g.mesh != nullptr);
    if (g.mesh) addMeshTriangles(g);
    else addPolygons(g);
    addExactShapes(g);
    for (int s = g.firstSurface; s < g.endSurface; ++s) {
        dvec3 lo, hi;
        shapeBounds(layout_.surfaces[s].shape, lo, hi);
        g.lo = glm::min(g.lo, lo), g.hi = glm::max(g.hi, hi);
    }
    if (k < 0) addPlacements();
    rtcCommitScene(g.scene);
}

void SceneGeometry::addPolygons(Group& g) {
    std::vector<dvec3> vertices;
    std::vector<unsigned> indices;
    for (int s = g.firstSurface; s < g.endSurface; ++s) {
        const auto* poly = std::get_if<Polygon>(&layout_.surfaces[s].shape);
        if (!poly) continue;
        unsigned first = static_cast<unsigned>(vertices.size());
        vertices.insert(vertices.end(), poly->vertices.begin(), poly->vertices.end());
        for (const auto& t : poly->triangles) {
            for (int k = 0; k < 3; ++k) indices.push_back(first + t[k]);
            g.triangleSurface.push_back(s);
        }
    }
    if (indices.empty()) return;
    RTCGeometry geom = newTriangles(device_, vertices, indices.data(), indices.size() / 3, false);
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryIntersectFilterFunction(geom, filterTriangle);
    attach(g.scene, geom, kTrianglesGeom);
}

// The mesh's own index buffer is shared with Embree: one copy of the triangles, however many placements.
void SceneGeometry::addMeshTriangles(Group& g) {
    const Mesh& m = *g.mesh;
    RTCGeometry geom = newTriangles(device_, m.vertices, m.triangles.front().data(), m.triangles.size(), true);
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryIntersectFilterFunction(geom, filterTriangle);
    attach(g.scene, geom, kTrianglesGeom);
    for (const dvec3& v : m.vertices) g.lo = glm::min(g.lo, v), g.hi = glm::max(g.hi, v);
}

void SceneGeometry::addExactShapes(Group& g) {
    for (int s = g.firstSurface; s < g.endSurface; ++s)
        if (!std::holds_alternative<Polygon>(layout_.surfaces[s].shape)) g.exactSurface.push_back(s);
    if (g.exactSurface.empty()) return;
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(g.exactSurface.size()));
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryBoundsFunction(geom, exactBounds, &g);
    rtcSetGeometryIntersectFunction(geom, exactIntersect);
    attach(g.scene, geom, kExactGeom);
}

// Placements beyond ±1e18, where Embree cannot trace in single precision, are left out.
void SceneGeometry::addPlacements() {
    for (size_t p = 0; p < layout_.placements.size(); ++p) {
        const Placement& placement = layout_.placements[p];
        if (!traceable(placement)) {
            warn("an instance or mesh reaches beyond ±1e18, where rays cannot be traced; dropped");
            continue;
        }
        RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geom, groups_[1 + placement.prototype].scene);
        float m[16];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[4 * c + r] = static_cast<float>(placement.transform.matrix[c][r]);
        rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, m);
        attach(groups_[0].scene, geom, kFirstPlacementGeom + unsigned(p));
    }
}

// The world box of a placement: the corners of its prototype's box, moved (empty for an empty prototype).
void SceneGeometry::placedBounds(const Placement& p, dvec3& lo, dvec3& hi) const {
    const Group& g = groups_[1 + p.prototype];
    lo = dvec3(std::numeric_limits<double>::infinity()), hi = -lo;
    if (g.lo.x > g.hi.x) return;
    for (int corner = 0; corner < 8; ++corner) {
        dvec3 c(corner & 1 ? g.hi.x : g.lo.x, corner & 2 ? g.hi.y : g.lo.y, corner & 4 ? g.hi.z : g.lo.z);
        dvec3 w = p.transform.point(c);
        lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
}

bool SceneGeometry::traceable(const Placement& p) const {
    dvec3 lo, hi;
    placedBounds(p, lo, hi);
    return lo.x > hi.x || !(glm::compMax(glm::max(glm::abs(lo), glm::abs(hi))) > 1e18);
}

// The world's box: its own surfaces' and its placements'.
void SceneGeometry::computeBounds() {
    lo_ = groups_[0].lo, hi_ = groups_[0].hi;
    for (const Placement& p : layout_.placements) {
        dvec3 lo, hi;
        placedBounds(p, lo, hi);
        if (traceable(p)) lo_ = glm::min(lo_, lo), hi_ = glm::max(hi_, hi);
    }
}

// Radiance: a surface (or mesh triangle) without a modifier of its own shows only where its instance gives one.
bool SceneGeometry::hidden(const SurfaceId& id) const {
    if (id.instance < 0) return false;
    const Placement& p = layout_.placements[id.instance];
    if (p.modifierObject >= 0) return false;
    if (id.triangle >= 0) return layout_.prototypes[p.prototype].mesh->materials[id.triangle] < 0;
    return layout_.surfaces[id.surface].voidModifier;
}

// The plane of a polygon or mesh triangle in its prototype's coordinates: its unit normal and a point of it.
void SceneGeometry::plane(const SurfaceId& id, dvec3& normal, dvec3& point) const {
    if (id.triangle < 0) {
        const auto& poly = std::get<Polygon>(layout_.surfaces[id.surface].shape);
        normal = poly.normal, point = poly.vertices[0];
        return;
    }
    const Mesh& m = *meshOf(id);
    const auto& tri = m.triangles[id.triangle];
    point = m.vertices[tri[0]];
    normal = glm::normalize(glm::cross(m.vertices[tri[1]] - point, m.vertices[tri[2]] - point));
}

// Whether a ray leaving a surface meets the polygon or mesh triangle `id` that Embree's float test proposes,
// decided in double precision in the prototype's coordinates. Planes that hold the ray's origin (to rounding)
// are those of the surface it leaves or of neighbours that meet it there (a polygon's coplanar neighbour, the
// next triangle of a mesh), crossed at the origin: not met. Nor is a neighbour of the mesh triangle it leaves
// that Embree claims for a crossing outside it right by the origin, at their shared edge. Elsewhere Embree's
// choice stands: its float test is watertight between triangles, a stricter one would not be. Rounding is
// relative to the coordinates' size, so this holds at any scale.
bool SceneGeometry::meetsFlat(const SurfaceId& id, const Ray& ray) const {
    const SurfaceId& from = ray.leaving;
    if (!from) return true;
    Ray local = localRay(ray, id.instance);
    dvec3 n, a;
    plane(id, n, a);
    double size = glm::compMax(glm::abs(local.org)) + glm::compMax(glm::abs(a));
    double height = glm::dot(n, local.org - a);
    double t = -height / glm::dot(n, local.dir);
    if (std::abs(height) <= 1e-12 * size || !(t > 0)) return false;
    if (id.triangle < 0 || from.triangle < 0 || from.instance != id.instance) return true;
    const Mesh& m = *meshOf(id);
    const auto &tri = m.triangles[id.triangle], &left = m.triangles[from.triangle];
    bool neighbour = std::find_first_of(tri.begin(), tri.end(), left.begin(), left.end()) != tri.end();
    dvec3 q = local.at(t);
    if (!neighbour || glm::length(q - local.org) > 1e-6 * size) return true;
    for (int k = 0; k < 3; ++k) {
        const dvec3 &v = m.vertices[tri[k]], &next = m.vertices[tri[(k + 1) % 3]];
        if (glm::dot(glm::cross(next - v, q - v), n) < 0) return false;
    }
    return true;
}

// The ray in a placement's prototype coordinates. Its direction is not normalized, so that distances along it
// are the world's.
Ray SceneGeometry::localRay(const Ray& ray, int placement) const {
    if (placement < 0) return ray;
    const Transform& inverse = layout_.placements[placement].inverse;
    Ray local = ray;
    local.org = inverse.point(ray.org);
    local.dir = inverse.vector(ray.dir);
    return local;
}

void SceneGeometry::filterTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<const TraceContext*>(args->context);
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        int placement = placementOf(RTCHitN_instID(args->hit, args->N, i, 0));
        SurfaceId id = g->idOf(kTrianglesGeom, RTCHitN_primID(args->hit, args->N, i), placement);
        bool meets = id != ctx->ray->leaving && !g->owner->hidden(id) && g->owner->meetsFlat(id, *ctx->ray);
        if (!meets) args->valid[i] = 0;
    }
}

void SceneGeometry::exactBounds(const RTCBoundsFunctionArguments* args) {
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    dvec3 lo, hi;
    shapeBounds(g->owner->layout_.surfaces[g->exactSurface[args->primID]].shape, lo, hi);
    // Widen by a relative margin so float rounding of the box never clips the exact shape.
    dvec3 pad = 1e-6 * (glm::abs(lo) + glm::abs(hi) + (hi - lo)) + 1e-30;
    lo -= pad, hi += pad;
    *args->bounds_o = RTCBounds{float(lo.x), float(lo.y), float(lo.z), 0, float(hi.x), float(hi.y), float(hi.z), 0};
}

void SceneGeometry::exactIntersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);  // rtcIntersect1 only: N is 1
    SurfaceId id = g->idOf(kExactGeom, args->primID, placementOf(args->context->instID[0]));
    if (g->owner->hidden(id)) return;
    Ray ray = g->owner->localRay(*ctx->ray, id.instance);
    ray.tmax = std::min(ray.tmax, static_cast<double>(rayhit->ray.tfar));
    bool leaving = id == ctx->ray->leaving;
    std::optional<ShapeHit> hit = std::visit(
        [&](const auto& shape) -> std::optional<ShapeHit> {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, Ring>) {
                if (leaving) return std::nullopt;
                return shape.intersect(ray);
            } else if constexpr (std::is_same_v<T, Polygon>) {
                return std::nullopt;
            } else {
                return shape.intersect(ray, leaving);
            }
        },
        g->owner->layout_.surfaces[id.surface].shape);
    if (!hit) return;
    rayhit->ray.tfar = static_cast<float>(hit->t);
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.instID[0] = args->context->instID[0];
    ctx->exactT = hit->t;
    ctx->exactNormal = hit->normal;
}

// The exact distance to a flat surface's plane (Embree's float t only chose the triangle), and its normal,
// in the ray's (prototype) coordinates.
double SceneGeometry::exactPlaneHit(const SurfaceId& id, const Ray& local, float embreeT, dvec3& normal) const {
    dvec3 point;
    plane(id, normal, point);
    double t = glm::dot(normal, point - local.org) / glm::dot(normal, local.dir);
    return t > 0 && std::isfinite(t) ? t : embreeT;
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.geometry = this;
    ctx.ray = &ray;
    RTCRayHit rh{};
    rh.ray.org_x = float(ray.org.x), rh.ray.org_y = float(ray.org.y), rh.ray.org_z = float(ray.org.z);
    rh.ray.dir_x = float(ray.dir.x), rh.ray.dir_y = float(ray.dir.y), rh.ray.dir_z = float(ray.dir.z);
    rh.ray.tnear = float(ray.tmin);
    rh.ray.tfar = ray.tmax > 3e38 ? std::numeric_limits<float>::infinity() : float(ray.tmax);
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    // Embree traces rays only within ±1.8e18 (its FLT_LARGE); farther ones meet nothing.
    for (float v : {rh.ray.org_x, rh.ray.org_y, rh.ray.org_z, rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z, rh.ray.tnear})
        if (!(std::abs(v) <= 1.8e18f)) return std::nullopt;
    rtcIntersect1(groups_[0].scene, &ctx.rtc, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    int placement = placementOf(rh.hit.instID[0]);
    const Group& g = groups_[placement < 0 ? 0 : 1 + layout_.placements[placement].prototype];
    SurfaceHit hit{0, dvec3(0), dvec3(0), g.idOf(rh.hit.geomID, rh.hit.primID, placement)};
    Ray local = localRay(ray, placement);
    dvec3 normal = ctx.exactNormal;
    hit.t = rh.hit.geomID == kExactGeom ? ctx.exactT : exactPlaneHit(hit.surface, local, rh.ray.tfar, normal);
    hit.point = ray.at(hit.t);
    // Radiance turns normals with the placement's matrix, mirror included: a mirrored surface keeps its front
    // where its mirrored normal points.
    hit.normal = placement < 0 ? normal : glm::normalize(layout_.placements[placement].transform.vector(normal));
    if (g.mesh) interpolateMesh(hit.surface, local, hit);
    return hit;
}

// Radiance's mesh shading: the vertex normals and (u, v) interpolated at the hit by its barycentric weights;
// the normal turned into the world and given as a perturbation of the geometric one.
void SceneGeometry::interpolateMesh(const SurfaceId& id, const Ray& local, SurfaceHit& hit) const {
    const Mesh& m = *meshOf(id);
    const auto& tri = m.triangles[id.triangle];
    const dvec3 &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    dvec3 n = glm::cross(b - a, c - a), q = local.at(hit.t);
    double n2 = glm::dot(n, n);
    if (!(n2 > 0)) return;
    double w[3] = {glm::dot(glm::cross(c - b, q - b), n) / n2, glm::dot(glm::cross(a - c, q - c), n) / n2, 0};
    w[2] = 1 - w[0] - w[1];
    if (!m.normals.empty()) {
        dvec3 shading(0);
        bool all = true;
        for (int k = 0; k < 3; ++k) {
            dvec3 vn(m.normals[tri[k]]);
            all = all && vn != dvec3(0);
            shading += w[k] * vn;
        }
        if (hit.surface.instance >= 0) shading = layout_.placements[hit.surface.instance].transform.vector(shading);
        if (all && glm::length(shading) > 0) hit.perturbation = glm::normalize(shading) - hit.normal;
    }
    if (!m.uvs.empty()) {
        glm::dvec2 uv = w[0] * m.uvs[tri[0]] + w[1] * m.uvs[tri[1]] + w[2] * m.uvs[tri[2]];
        if (!std::isnan(uv.x) && !std::isnan(uv.y)) hit.uv = uv;
    }
}

}  // namespace brume
