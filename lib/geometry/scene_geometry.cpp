#include "geometry/scene_geometry.h"

#include <cmath>
#include <limits>

#include "geometry/polygon.h"
#include "geometry/scene_geometry_group.h"

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

// A triangle geometry with a float copy of `vertices` and the given index buffer.
RTCGeometry newTriangles(RTCDevice device, const std::vector<dvec3>& vertices, const unsigned* indices, size_t count,
                         bool shareIndices) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), vertices.size()));
    for (size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vb[3 * i + k] = static_cast<float>(vertices[i][k]);
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

void scene_geometry_detail::shapeBounds(const Shape& shape, dvec3& lo, dvec3& hi) {
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
    if (g.mesh)
        addMeshTriangles(g);
    else
        addPolygons(g);
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
    rtcSetGeometryOccludedFilterFunction(geom, filterShadowTriangle);
    attach(g.scene, geom, kTrianglesGeom);
}

// The mesh's own index buffer is shared with Embree: one copy of the triangles, however many placements.
void SceneGeometry::addMeshTriangles(Group& g) {
    const Mesh& m = *g.mesh;
    RTCGeometry geom = newTriangles(device_, m.vertices, m.triangles.front().data(), m.triangles.size(), true);
    rtcSetGeometryUserData(geom, &g);
    rtcSetGeometryIntersectFilterFunction(geom, filterTriangle);
    rtcSetGeometryOccludedFilterFunction(geom, filterShadowTriangle);
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
    rtcSetGeometryOccludedFunction(geom, exactOccluded);
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

}  // namespace brume
