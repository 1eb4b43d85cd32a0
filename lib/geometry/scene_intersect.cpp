// SceneGeometry's tracing: Embree's candidates, decided and completed in double precision.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/scene_geometry_group.h"

namespace brume {

using namespace scene_geometry_detail;

namespace {

// An occlusion query's question and what its candidates tell.
struct ShadowQuery {
    const ShadowBlockers* blockers;
    SurfaceId target;
    double sureEnd;  // candidates beyond are within rounding of the target, in either order
    bool unsure = false;   // the query ended on a candidate only the walk can judge
    bool crossed = false;  // it passed surfaces that may let light through

    // Whether a candidate at distance t ends the query.
    bool ends(const SurfaceId& id, double t) {
        bool nearEnd = t >= sureEnd;
        if (id == target && nearEnd) return false;  // the target itself: no obstacle
        bool before = !nearEnd && id != target;      // surely met before the target
        if (before && blockers->blocksShadows(id)) return true;
        if (before && blockers->blockersDecide()) {  // look past it for a blocker, which decides
            crossed = true;
            return false;
        }
        unsure = true;
        return true;
    }
};

// Embree's per-query context, extended with the exact ray and the exact hit of our own shapes.
struct TraceContext {
    RTCIntersectContext rtc;
    const SceneGeometry* geometry;
    const Ray* ray;  // in world coordinates
    double exactT;
    dvec3 exactNormal;  // in the coordinates of the shape's prototype
    ShadowQuery* shadow = nullptr;  // occlusion queries only
};

// The ray in Embree's single precision; false where Embree cannot trace it: it traces only within ±1.8e18
// (its FLT_LARGE).
bool toEmbree(const Ray& ray, RTCRay& r) {
    r.org_x = float(ray.org.x), r.org_y = float(ray.org.y), r.org_z = float(ray.org.z);
    r.dir_x = float(ray.dir.x), r.dir_y = float(ray.dir.y), r.dir_z = float(ray.dir.z);
    r.tnear = float(ray.tmin);
    r.tfar = ray.tmax > 3e38 ? std::numeric_limits<float>::infinity() : float(ray.tmax);
    r.mask = ~0u;
    r.time = 0, r.id = 0, r.flags = 0;
    for (float v : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z, r.tnear})
        if (!(std::abs(v) <= 1.8e18f)) return false;
    return true;
}

}  // namespace

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

// The surface of a filter call's candidate triangle i.
SurfaceId SceneGeometry::candidate(const RTCFilterFunctionNArguments* args, unsigned i) {
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    int placement = placementOf(RTCHitN_instID(args->hit, args->N, i, 0));
    return g->idOf(kTrianglesGeom, RTCHitN_primID(args->hit, args->N, i), placement);
}

// Whether the ray meets the flat surface (or mesh triangle) Embree proposes.
bool SceneGeometry::meetsTriangle(const SurfaceId& id, const Ray& ray) const {
    return id != ray.leaving && !hidden(id) && meetsFlat(id, ray);
}

void SceneGeometry::filterTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<const TraceContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] && !ctx->geometry->meetsTriangle(candidate(args, i), *ctx->ray)) args->valid[i] = 0;
}

// Occlusion queries: Embree gives the candidate's distance as the ray's tfar. Nearly every shadow ray meets its
// target, which needs no exact test: near the end it is ignored, before it left to the walk.
void SceneGeometry::filterShadowTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<const TraceContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        SurfaceId id = candidate(args, i);
        bool met = id == ctx->shadow->target || ctx->geometry->meetsTriangle(id, *ctx->ray);
        if (!met || !ctx->shadow->ends(id, RTCRayN_tfar(args->ray, args->N, i))) args->valid[i] = 0;
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
    std::optional<ShapeHit> hit = g->owner->exactHit(id, *ctx->ray, rayhit->ray.tfar);
    if (!hit) return;
    rayhit->ray.tfar = static_cast<float>(hit->t);
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.instID[0] = args->context->instID[0];
    ctx->exactT = hit->t;
    ctx->exactNormal = hit->normal;
}

// Occlusion queries (rtcOccluded1 only: N is 1); Embree's mark of a ray found blocked is tfar = -∞.
void SceneGeometry::exactOccluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    SurfaceId id = g->idOf(kExactGeom, args->primID, placementOf(args->context->instID[0]));
    std::optional<ShapeHit> hit = g->owner->exactHit(id, *ctx->ray, ray->tfar);
    if (hit && ctx->shadow->ends(id, hit->t)) ray->tfar = -std::numeric_limits<float>::infinity();
}

// The exact shape `id`'s hit by the world ray before Embree's current tfar, its own root at the ray's origin
// skipped when the ray leaves it.
std::optional<ShapeHit> SceneGeometry::exactHit(const SurfaceId& id, const Ray& world, float tfar) const {
    if (hidden(id)) return std::nullopt;
    Ray ray = localRay(world, id.instance);
    ray.tmax = std::min(ray.tmax, static_cast<double>(tfar));
    bool leaving = id == world.leaving;
    return std::visit(
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
        layout_.surfaces[id.surface].shape);
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
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (!toEmbree(ray, rh.ray)) return std::nullopt;  // farther rays meet nothing
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

Occlusion SceneGeometry::occlusion(const Ray& ray, const SurfaceId& target, double distance,
                                   const ShadowBlockers& blockers) const {
    Ray shadow = ray;
    ShadowQuery query{&blockers, target, distance};
    if (std::isfinite(distance)) {
        // Embree's float distances round relative to the coordinates' size; the walk orders hits by them.
        double margin = 1e-5 * (distance + glm::compMax(glm::abs(ray.org)));
        query.sureEnd = distance - margin;
        shadow.tmax = distance + margin;
    }
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.geometry = this;
    ctx.ray = &shadow;
    ctx.shadow = &query;
    RTCRay r{};
    if (!toEmbree(shadow, r)) return Occlusion::Unsure;
    rtcOccluded1(groups_[0].scene, &ctx.rtc, &r);
    if (r.tfar >= 0) return query.crossed ? Occlusion::Unsure : Occlusion::Clear;
    return query.unsure || !blockers.blockersDecide() ? Occlusion::Unsure : Occlusion::Blocked;
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
