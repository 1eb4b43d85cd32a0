#include "world/scene_geometry.h"

#include <cmath>
#include <limits>

#include "geometry/polygon.h"
#include "world/scene_geometry_group.h"

namespace brume {

using namespace scene_geometry_detail;

namespace {

// Axis-aligned half extent of a disk of radius r whose plane has unit normal n.
dvec3 diskExtent(const dvec3& n, double r) {
    return r * glm::sqrt(glm::max(dvec3(0), dvec3(1) - n * n));
}

// Meshes, where the memory goes, get Embree's compact structures: a fifth less memory for a 1M-triangle mesh,
// no measurable loss of speed.
RTCScene newScene(RTCDevice device, bool compact) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, compact ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT : RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    return scene;
}

// A triangle geometry with a float copy of `vertices` as offsets from `origin`, and the given index buffer.
RTCGeometry newTriangles(RTCDevice device, const std::vector<dvec3>& vertices, const dvec3& origin,
                         const unsigned* indices, size_t count, bool shareIndices) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), vertices.size()));
    for (size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vb[3 * i + k] = static_cast<float>(vertices[i][k] - origin[k]);
    if (shareIndices) {
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0, 3 * sizeof(unsigned),
                                   count);
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

Bounds3 scene_geometry_detail::triangleBounds(const Mesh& mesh, size_t t) {
    Bounds3 b;
    for (uint32_t v : mesh.triangles[t]) b.include(mesh.vertices[v]);
    return b;
}

Bounds3 scene_geometry_detail::shapeBounds(const Shape& shape) {
    struct {
        Bounds3 operator()(const Sphere& s) const { return {s.center - s.radius, s.center + s.radius}; }
        Bounds3 operator()(const Cone& c) const {
            dvec3 a = glm::normalize(c.top - c.base);
            dvec3 e0 = diskExtent(a, c.baseRadius), e1 = diskExtent(a, c.topRadius);
            return {glm::min(c.base - e0, c.top - e1), glm::max(c.base + e0, c.top + e1)};
        }
        Bounds3 operator()(const Ring& r) const {
            dvec3 e = diskExtent(r.normal, r.outerRadius);
            return {r.center - e, r.center + e};
        }
        Bounds3 operator()(const Polygon& p) const {
            Bounds3 b;
            for (const dvec3& v : p.vertices) b.include(v);
            return b;
        }
    } visit;
    return std::visit(visit, shape);
}

SceneGeometry::SceneGeometry(std::vector<Surface> surfaces) : SceneGeometry(ownSurfacesOnly(std::move(surfaces))) {}

// The world's frame is found first: its typical size also bounds what a prototype may hold as float
// triangles, so that a prototype that is one huge ground is exact too.
SceneGeometry::SceneGeometry(SceneLayout layout) : layout_(std::move(layout)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("cannot create Embree device");
    groups_.resize(1 + layout_.prototypes.size());
    std::vector<std::vector<Bounds3>> pieces(groups_.size());
    for (size_t g = 0; g < groups_.size(); ++g) pieces[g] = pieceBoxes(groups_[g], int(g) - 1);
    std::vector<Bounds3> world = pieces[0];
    std::vector<double> largestScale(layout_.prototypes.size(), 0);
    for (const Placement& p : layout_.placements) {
        world.push_back(placedBounds(p));
        largestScale[p.prototype] = std::max(largestScale[p.prototype], std::abs(p.transform.scale));
    }
    groups_[0].frame = LocalFrame(world);
    for (size_t k = 0; k < layout_.prototypes.size(); ++k) {
        double worldTypical = groups_[0].frame.typicalSize() / std::max(largestScale[k], 1e-300);
        groups_[1 + k].frame = LocalFrame(pieces[1 + k], worldTypical);
        buildGroup(groups_[1 + k]);
    }
    buildGroup(groups_[0]);
    addPlacements(world);
    rtcCommitScene(groups_[0].scene);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw Error("Embree failed to build the scene");
}

SceneGeometry::~SceneGeometry() {
    for (Group& g : groups_)
        if (g.scene) rtcReleaseScene(g.scene);
    if (device_) rtcReleaseDevice(device_);
}

// Prototype k's group, or with k = -1 the world's (its own surfaces), told what it holds and its box; returns
// the boxes its frame is found from: its surfaces', or a mesh's triangles', at most kFrameSample of them
// taken evenly (the medians of a million triangles need no more, nor a million boxes in memory).
std::vector<Bounds3> SceneGeometry::pieceBoxes(Group& g, int k) const {
    constexpr size_t kFrameSample = size_t(1) << 16;
    g.owner = this;
    g.endSurface = layout_.ownSurfaces;
    if (k >= 0) {
        const Prototype& p = layout_.prototypes[k];
        g.firstSurface = p.firstSurface, g.endSurface = p.endSurface, g.mesh = p.mesh;
    }
    std::vector<Bounds3> boxes;
    for (int s = g.firstSurface; s < g.endSurface; ++s) boxes.push_back(shapeBounds(layout_.surfaces[s].shape));
    for (const Bounds3& b : boxes) g.box.include(b);
    if (!g.mesh) return boxes;
    for (const dvec3& v : g.mesh->vertices) g.box.include(v);
    size_t count = g.mesh->triangles.size(), stride = std::max<size_t>(1, count / kFrameSample);
    for (size_t t = 0; t < count; t += stride) boxes.push_back(triangleBounds(*g.mesh, t));
    return boxes;
}

// A group's Embree scene, its frame set; the world's is committed once its placements are added.
void SceneGeometry::buildGroup(Group& g) {
    g.scene = newScene(device_, g.mesh != nullptr);
    if (g.mesh)
        addMeshTriangles(g);
    else
        addPolygons(g);
    addExactShapes(g);
    if (&g != &groups_[0]) rtcCommitScene(g.scene);
}

// Flat pieces of ordinary size near the group's origin become float triangles; the others (huge or far
// ones, whose float rounding would be too coarse for what lies near them) exact shapes.
bool SceneGeometry::floatPiece(const Group& g, const Bounds3& box) { return !g.frame.huge(box) && g.frame.near(box); }

bool SceneGeometry::floatPolygon(const Group& g, int s) const {
    const Shape& shape = layout_.surfaces[s].shape;
    return std::holds_alternative<Polygon>(shape) && floatPiece(g, shapeBounds(shape));
}

void SceneGeometry::addPolygons(Group& g) {
    std::vector<dvec3> vertices;
    std::vector<unsigned> indices;
    for (int s = g.firstSurface; s < g.endSurface; ++s) {
        if (!floatPolygon(g, s)) continue;
        const auto& poly = std::get<Polygon>(layout_.surfaces[s].shape);
        unsigned first = static_cast<unsigned>(vertices.size());
        vertices.insert(vertices.end(), poly.vertices.begin(), poly.vertices.end());
        for (size_t t = 0; t < poly.triangles.size(); ++t) {
            for (int c = 0; c < 3; ++c) indices.push_back(first + poly.triangles[t][c]);
            g.triangles.push_back({s, int(t)});
        }
        g.floatReach = std::max(g.floatReach, reachFrom(shapeBounds(poly), g.frame.origin()));
    }
    if (indices.empty()) return;
    RTCGeometry geom = newTriangles(device_, vertices, g.frame.origin(), indices.data(), indices.size() / 3, false);
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryIntersectFilterFunction(geom, filterTriangle);
    rtcSetGeometryOccludedFilterFunction(geom, filterShadowTriangle);
    attach(g.scene, geom, kTrianglesGeom);
}

// The mesh's own index buffer is shared with Embree (one copy of the triangles, however many placements)
// unless some of its triangles are exact shapes; then the float ones get an index buffer of their own, and
// their primIDs map to the mesh's.
void SceneGeometry::addMeshTriangles(Group& g) {
    const Mesh& m = *g.mesh;
    std::vector<bool> isFloat(m.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        Bounds3 b = triangleBounds(m, t);
        isFloat[t] = floatPiece(g, b);
        if (isFloat[t]) g.floatReach = std::max(g.floatReach, reachFrom(b, g.frame.origin()));
        else g.exact.push_back({-1, int(t)});
    }
    if (g.exact.size() == m.triangles.size()) return;
    RTCGeometry geom;
    if (g.exact.empty()) {
        geom = newTriangles(device_, m.vertices, g.frame.origin(), m.triangles.front().data(), m.triangles.size(), true);
    } else {
        std::vector<unsigned> indices;
        for (size_t t = 0; t < m.triangles.size(); ++t) {
            if (!isFloat[t]) continue;
            g.triangles.push_back({-1, int(t)});
            indices.insert(indices.end(), m.triangles[t].begin(), m.triangles[t].end());
        }
        geom = newTriangles(device_, m.vertices, g.frame.origin(), indices.data(), indices.size() / 3, false);
    }
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryIntersectFilterFunction(geom, filterTriangle);
    rtcSetGeometryOccludedFilterFunction(geom, filterShadowTriangle);
    attach(g.scene, geom, kTrianglesGeom);
}

// Spheres, cones and rings, and the triangles of polygons and meshes that are not float triangles (those of
// meshes found by addMeshTriangles): user geometry, intersected in double precision.
void SceneGeometry::addExactShapes(Group& g) {
    for (int s = g.firstSurface; s < g.endSurface; ++s) {
        if (floatPolygon(g, s)) continue;
        if (const auto* poly = std::get_if<Polygon>(&layout_.surfaces[s].shape))
            for (size_t t = 0; t < poly->triangles.size(); ++t) g.exact.push_back({s, int(t)});
        else
            g.exact.push_back({s, -1});
    }
    if (g.exact.empty()) return;
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(g.exact.size()));
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryBoundsFunction(geom, exactBounds, &g);
    rtcSetGeometryIntersectFunction(geom, exactIntersect);
    rtcSetGeometryOccludedFunction(geom, exactOccluded);
    attach(g.scene, geom, kExactGeom);
}

// Placements beyond ±1e18, where Embree cannot trace in single precision, are left out. Each instance's
// float transform takes its prototype's offsets to the world's: p_world − O_world = A (p_proto − O_proto)
// + (A O_proto + t − O_world), whose translation is small for copies near the world's origin.
void SceneGeometry::addPlacements(const std::vector<Bounds3>& items) {
    Group& world = groups_[0];
    placementShift_.assign(layout_.placements.size(), 0);
    placementNear_.assign(layout_.placements.size(), false);
    for (size_t p = 0; p < layout_.placements.size(); ++p) {
        const Placement& placement = layout_.placements[p];
        const Bounds3& placed = items[world.endSurface - world.firstSurface + p];
        if (!traceable(placed)) {
            warn("an instance or mesh reaches beyond ±1e18, where rays cannot be traced; dropped");
            continue;
        }
        const Group& proto = groups_[1 + placement.prototype];
        const glm::dmat4& m = placement.transform.matrix;
        dvec3 shift = placement.transform.point(proto.frame.origin()) - world.frame.origin();
        placementShift_[p] = glm::compMax(glm::abs(shift));
        placementNear_[p] = world.frame.near(placed);
        // Its float triangles round in the world's float coordinates by as much as the farthest of them lies
        // from the world's origin; where rays start near them, Embree's ray must start so far behind.
        if (world.frame.reaches(placed) && proto.floatReach > 0)
            world.floatReach = std::max(world.floatReach, placementShift_[p] + std::abs(placement.transform.scale) * proto.floatReach);
        float f[16];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) f[4 * c + r] = static_cast<float>(c < 3 ? m[c][r] : r < 3 ? shift[r] : 1.0);
        RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geom, proto.scene);
        rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, f);
        attach(world.scene, geom, kFirstPlacementGeom + unsigned(p));
        world.box.include(placed);
    }
    // The scene's scale: what is neither huge nor far; all of it where nothing is ordinary.
    for (const Bounds3& b : items)
        if (traceable(b) && !world.frame.huge(b) && world.frame.near(b)) extent_.include(b);
    if (extent_.empty()) extent_ = world.box;
}

dvec3 SceneGeometry::origin() const { return groups_[0].frame.origin(); }

// The world box of a placement: the corners of its prototype's box, moved (empty for an empty prototype).
Bounds3 SceneGeometry::placedBounds(const Placement& p) const {
    const Bounds3& box = groups_[1 + p.prototype].box;
    Bounds3 placed;
    if (box.empty()) return placed;
    for (int corner = 0; corner < 8; ++corner) {
        dvec3 c(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y, corner & 4 ? box.hi.z : box.lo.z);
        placed.include(p.transform.point(c));
    }
    return placed;
}

bool SceneGeometry::traceable(const Bounds3& b) {
    return b.empty() || !(glm::compMax(glm::max(glm::abs(b.lo), glm::abs(b.hi))) > 1e18);
}

}  // namespace brume
