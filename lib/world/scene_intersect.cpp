// SceneGeometry's tracing: Embree's float BVH proposes candidates; each is decided, and the nearest chosen,
// in double precision.
#include <algorithm>
#include <cmath>
#include <limits>

#include "world/scene_geometry_group.h"

namespace brume {

using namespace scene_geometry_detail;

// An occlusion query's question and what its candidates tell.
struct SceneGeometry::ShadowQuery {
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

// Embree's per-query context, extended with the exact ray and the nearest exact hit so far.
struct SceneGeometry::TraceContext {
    RTCIntersectContext rtc;
    const SceneGeometry* geometry;
    const Ray* ray;  // in world coordinates
    // Embree's ray starts this far behind ray->org (its distances are t + behind), so that candidates its
    // rounding puts just behind the origin are still proposed; it is the float rounding near the origin.
    double behind = 0;
    double bestT = std::numeric_limits<double>::infinity();
    SurfaceId bestId;
    dvec3 bestNormal{0};  // in the coordinates of the shape's prototype
    ShadowQuery* shadow = nullptr;  // occlusion queries only

    // The rounding of Embree's float view of a point at distance t along the ray, in world units.
    double rounding(double t) const { return behind + kFloatError * t; }
    // Embree's far end once an exact hit at t is found: candidates its rounding may have put beyond t
    // are still proposed, and judged by their exact distance.
    float farEnd(double t) const { return std::nextafter(float(t + behind + rounding(t)), INFINITY); }
    // Takes an exact hit if it is the nearest so far; false if not.
    bool take(double t, const SurfaceId& id, const dvec3& normal) {
        if (!(t < bestT)) return false;
        bestT = t, bestId = id, bestNormal = normal;
        return true;
    }
};

// Radiance: a surface (or mesh triangle) without a modifier of its own shows only where its instance gives one.
bool SceneGeometry::hidden(const SurfaceId& id) const {
    if (id.instance < 0) return false;
    const Placement& p = layout_.placements[id.instance];
    if (p.modifierObject >= 0) return false;
    if (id.triangle >= 0) return layout_.prototypes[p.prototype].mesh->materials[id.triangle] < 0;
    return layout_.surfaces[id.surface].voidModifier;
}

// A polygon's triangle `triangle` or a mesh triangle, in its prototype's coordinates, with the plane hits
// are put on: the polygon's (Newell) plane, or the mesh triangle's own.
SceneGeometry::FlatPiece SceneGeometry::flatPiece(const SurfaceId& id, int triangle) const {
    FlatPiece f;
    if (id.triangle < 0) {
        const auto& poly = std::get<Polygon>(layout_.surfaces[id.surface].shape);
        for (int k = 0; k < 3; ++k) f.corner[k] = &poly.vertices[poly.triangles[triangle][k]];
        f.normal = poly.normal, f.onPlane = &poly.vertices[0];
        return f;
    }
    const Mesh& m = *meshOf(id);
    for (int k = 0; k < 3; ++k) f.corner[k] = &m.vertices[m.triangles[id.triangle][k]];
    f.normal = glm::normalize(glm::cross(*f.corner[1] - *f.corner[0], *f.corner[2] - *f.corner[0]));
    f.onPlane = f.corner[0];
    return f;
}

// The exact distance at which the world ray meets a flat piece of surface `id` within the ray's
// [tmin, tmax], or nullopt. Whether it meets it inside the piece's triangle is Embree's float test's word
// where that is precise (no `slack`); else the crossing must lie within the triangle widened by `slack`
// (prototype units: how far rounding may have put it). Planes that hold the origin of a ray leaving a
// surface (to rounding) are those of the surface it leaves or of neighbours that meet it there (a
// polygon's coplanar neighbour, the next triangle of a mesh), crossed at the origin: not met. Nor is a
// neighbour of the mesh triangle it leaves crossed outside it right by the origin, at their shared edge.
// Rounding is relative to the coordinates' size, so this holds at any scale.
std::optional<double> SceneGeometry::flatHit(const SurfaceId& id, const FlatPiece& f, const Ray& world,
                                             std::optional<double> slack) const {
    Ray local = localRay(world, id.instance);
    double size = glm::compMax(glm::abs(local.org)) + glm::compMax(glm::abs(*f.onPlane));
    double height = glm::dot(f.normal, local.org - *f.onPlane);
    double t = -height / glm::dot(f.normal, local.dir);
    if (!(t > world.tmin && t < world.tmax)) return std::nullopt;
    const SurfaceId& from = world.leaving;
    if (from && std::abs(height) <= 1e-12 * size) return std::nullopt;
    dvec3 q = local.at(t);
    if (id.triangle >= 0 && from.triangle >= 0 && from.instance == id.instance &&
        glm::length(q - local.org) <= 1e-6 * size) {
        const Mesh& m = *meshOf(id);
        const auto &tri = m.triangles[id.triangle], &left = m.triangles[from.triangle];
        if (std::find_first_of(tri.begin(), tri.end(), left.begin(), left.end()) != tri.end()) slack = 0;
    }
    if (slack && !within(f, q, *slack)) return std::nullopt;
    return t;
}

// Whether point q of the piece's plane lies within its triangle widened by `slack`.
bool SceneGeometry::within(const FlatPiece& f, const dvec3& q, double slack) {
    const dvec3 &a = *f.corner[0], &b = *f.corner[1], &c = *f.corner[2];
    // Triangulations may turn either way about the normal.
    dvec3 n = glm::dot(glm::cross(b - a, c - a), f.normal) < 0 ? -f.normal : f.normal;
    for (int k = 0; k < 3; ++k) {
        const dvec3 &v = *f.corner[k], &next = *f.corner[(k + 1) % 3];
        if (glm::dot(glm::cross(next - v, q - v), n) < -slack * glm::length(next - v)) return false;
    }
    return true;
}

// How far, in its prototype's units, Embree's rounding may put a crossing of a float triangle of surface
// `id` at distance t: the ray's rounding, that of the instance's float transform, and that of the
// triangle's own float vertices; nullopt where Embree's float test is precise (the world's own triangles,
// and placements near its origin, whose float coordinates are small).
std::optional<double> SceneGeometry::floatSlack(const SurfaceId& id, double t, const TraceContext& ctx) const {
    if (id.instance < 0 || placementNear_[id.instance]) return std::nullopt;
    const Placement& p = layout_.placements[id.instance];
    double world = ctx.rounding(t) + kFloatError * (placementShift_[id.instance] + groups_[0].floatReach);
    return world / std::abs(p.transform.scale) + kFloatError * groupOf(id).floatReach;
}

const SceneGeometry::Group& SceneGeometry::groupOf(const SurfaceId& id) const {
    return groups_[id.instance < 0 ? 0 : 1 + layout_.placements[id.instance].prototype];
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

// Where the world ray meets the float triangle Embree proposes (filter call candidate i), exactly; nullopt
// for a miss, a hidden surface or the surface the ray leaves.
std::optional<SceneGeometry::Candidate> SceneGeometry::floatCandidate(const RTCFilterFunctionNArguments* args,
                                                                      unsigned i, const TraceContext& ctx) {
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    int placement = placementOf(RTCHitN_instID(args->hit, args->N, i, 0));
    unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    Candidate c{0, g->idOf(kTrianglesGeom, prim, placement), dvec3(0)};
    // Nearly every shadow ray meets its target, which, flat, it can meet only there: no exact test.
    if (ctx.shadow && c.id == ctx.shadow->target) {
        c.t = ctx.shadow->sureEnd;
        return c;
    }
    const SceneGeometry& geometry = *ctx.geometry;
    if (c.id == ctx.ray->leaving || geometry.hidden(c.id)) return std::nullopt;
    FlatPiece f = geometry.flatPiece(c.id, g->mesh ? -1 : g->triangles[prim].triangle);
    c.normal = f.normal;
    // The slack at the distance Embree found, less its start behind the origin: close enough to the exact one.
    double embreeT = std::max(0.0, double(RTCRayN_tfar(args->ray, args->N, i)) - ctx.behind);
    std::optional<double> t = geometry.flatHit(c.id, f, *ctx.ray, geometry.floatSlack(c.id, embreeT, ctx));
    if (!t) return std::nullopt;
    c.t = *t;
    return c;
}

void SceneGeometry::filterTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        std::optional<Candidate> c = floatCandidate(args, i, *ctx);
        if (c && ctx->take(c->t, c->id, c->normal))
            RTCRayN_tfar(args->ray, args->N, i) = ctx->farEnd(c->t);
        else
            args->valid[i] = 0;
    }
}

// Occlusion queries: each candidate's exact distance tells whether it lies before the target.
void SceneGeometry::filterShadowTriangle(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        std::optional<Candidate> c = floatCandidate(args, i, *ctx);
        if (!c || !ctx->shadow->ends(c->id, c->t)) args->valid[i] = 0;
    }
}

// The box of an exact primitive in its group's float coordinates, widened by a relative margin so that
// float rounding never clips the exact shape.
void SceneGeometry::exactBounds(const RTCBoundsFunctionArguments* args) {
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    const Piece& piece = g->exact[args->primID];
    Bounds3 b;
    if (piece.surface < 0) {
        b = triangleBounds(*g->mesh, piece.triangle);
    } else if (piece.triangle < 0) {
        b = shapeBounds(g->owner->layout_.surfaces[piece.surface].shape);
    } else {
        const auto& poly = std::get<Polygon>(g->owner->layout_.surfaces[piece.surface].shape);
        for (int k : poly.triangles[piece.triangle]) b.include(poly.vertices[k]);
    }
    dvec3 lo = b.lo - g->frame.origin(), hi = b.hi - g->frame.origin();
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
    std::optional<ShapeHit> hit = g->owner->exactHit(*g, args->primID, id, *ctx->ray, ctx->bestT);
    if (!hit || !ctx->take(hit->t, id, hit->normal)) return;
    rayhit->ray.tfar = ctx->farEnd(hit->t);
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.instID[0] = args->context->instID[0];
}

// Occlusion queries (rtcOccluded1 only: N is 1); Embree's mark of a ray found blocked is tfar = -∞.
void SceneGeometry::exactOccluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* g = static_cast<const Group*>(args->geometryUserPtr);
    auto* ctx = reinterpret_cast<TraceContext*>(args->context);
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    SurfaceId id = g->idOf(kExactGeom, args->primID, placementOf(args->context->instID[0]));
    std::optional<ShapeHit> hit = g->owner->exactHit(*g, args->primID, id, *ctx->ray, ctx->ray->tmax);
    if (hit && ctx->shadow->ends(id, hit->t)) ray->tfar = -std::numeric_limits<float>::infinity();
}

// Exact primitive `prim`'s hit by the world ray before `tmax`, its own root at the ray's origin skipped when
// the ray leaves it. Polygon triangles are widened only by double rounding, so that neither a polygon's
// own triangles nor neighbours sharing an edge leave a crack.
std::optional<ShapeHit> SceneGeometry::exactHit(const Group& g, unsigned prim, const SurfaceId& id, const Ray& world,
                                                double tmax) const {
    if (hidden(id)) return std::nullopt;
    Ray ray = localRay(world, id.instance);
    ray.tmax = std::min(ray.tmax, tmax);
    bool leaving = id == world.leaving;
    if (id.triangle >= 0 || std::holds_alternative<Polygon>(layout_.surfaces[id.surface].shape)) {
        if (leaving) return std::nullopt;
        FlatPiece f = flatPiece(id, g.exact[prim].triangle);
        Ray bounded = world;
        bounded.tmax = ray.tmax;
        double size = glm::compMax(glm::abs(ray.org)) + glm::length(*f.corner[1] - *f.corner[0]) +
                      glm::length(*f.corner[2] - *f.corner[0]);
        std::optional<double> t = flatHit(id, f, bounded, 1e-12 * size);
        if (!t) return std::nullopt;
        return ShapeHit{*t, f.normal};
    }
    const Shape& shape = layout_.surfaces[id.surface].shape;
    return std::visit(
        [&](const auto& s) -> std::optional<ShapeHit> {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, Ring>) {
                if (leaving) return std::nullopt;
                return s.intersect(ray);
            } else if constexpr (std::is_same_v<T, Polygon>) {
                return std::nullopt;  // flat pieces are met above
            } else {
                return s.intersect(ray, leaving);
            }
        },
        shape);
}

// The ray as Embree's float ray in the world group's coordinates, started `behind` its origin by the float
// rounding of the origin and of the geometry near it; false where Embree cannot trace it: it traces only
// within ±1.8e18 (its FLT_LARGE).
bool SceneGeometry::toEmbree(const Ray& ray, RTCRay& r, double& behind) const {
    const Group& world = groups_[0];
    dvec3 local = ray.org - world.frame.origin();
    auto traceable = [](const dvec3& v) { return std::abs(v.x) <= 1.8e18 && std::abs(v.y) <= 1.8e18 && std::abs(v.z) <= 1.8e18; };
    if (!traceable(local) || !traceable(ray.dir) || !(ray.tmin <= 1.8e18)) return false;
    double reach = glm::compMax(glm::abs(local));
    behind = kFloatError * (reach + world.floatReach);
    dvec3 org = local - behind * ray.dir;
    r.org_x = float(org.x), r.org_y = float(org.y), r.org_z = float(org.z);
    r.dir_x = float(ray.dir.x), r.dir_y = float(ray.dir.y), r.dir_z = float(ray.dir.z);
    r.tnear = float(std::max(0.0, ray.tmin));
    double far = ray.tmax + behind + (behind + kFloatError * ray.tmax);
    r.tfar = far > 3e38 ? std::numeric_limits<float>::infinity() : float(far);
    r.mask = ~0u;
    r.time = 0, r.id = 0, r.flags = 0;
    return true;
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.geometry = this;
    ctx.ray = &ray;
    RTCRayHit rh{};
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (!toEmbree(ray, rh.ray, ctx.behind)) return std::nullopt;  // farther rays meet nothing
    rtcIntersect1(groups_[0].scene, &ctx.rtc, &rh);
    if (!ctx.bestId) return std::nullopt;
    SurfaceHit hit{ctx.bestT, ray.at(ctx.bestT), dvec3(0), ctx.bestId};
    int placement = ctx.bestId.instance;
    // Radiance turns normals with the placement's matrix, mirror included: a mirrored surface keeps its front
    // where its mirrored normal points.
    hit.normal = placement < 0 ? ctx.bestNormal
                               : glm::normalize(layout_.placements[placement].transform.vector(ctx.bestNormal));
    if (ctx.bestId.triangle >= 0) interpolateMesh(hit.surface, localRay(ray, placement), hit);
    return hit;
}

Occlusion SceneGeometry::occlusion(const Ray& ray, const SurfaceId& target, double distance,
                                   const ShadowBlockers& blockers) const {
    Ray shadow = ray;
    ShadowQuery query{&blockers, target, distance};
    if (std::isfinite(distance)) {
        // Exact distances round only in double precision: relative to the distance and the coordinates.
        double margin = 1e-9 * distance + 1e-12 * glm::compMax(glm::abs(ray.org));
        query.sureEnd = distance - margin;
        shadow.tmax = distance + margin;
    }
    TraceContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.geometry = this;
    ctx.ray = &shadow;
    ctx.shadow = &query;
    RTCRay r{};
    if (!toEmbree(shadow, r, ctx.behind)) return Occlusion::Unsure;
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
