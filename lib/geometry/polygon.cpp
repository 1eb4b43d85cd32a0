#include "geometry/polygon.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <glm/geometric.hpp>

namespace brume {

std::optional<Polygon> makePolygon(std::vector<dvec3> vertices, std::string& why) {
    // Repeated consecutive vertices add nothing and would make zero-length edges.
    std::vector<dvec3> v;
    for (const dvec3& p : vertices)
        if (v.empty() || p != v.back()) v.push_back(p);
    while (v.size() > 1 && v.front() == v.back()) v.pop_back();
    if (v.size() < 3) {
        why = "fewer than 3 distinct vertices";
        return std::nullopt;
    }
    // Newell's method: the area-weighted normal, robust for concave and slightly non-planar polygons.
    // Vertices are taken relative to the first so huge coordinates do not swamp small polygons.
    dvec3 n(0), extent(0);
    for (size_t i = 0; i < v.size(); ++i) {
        dvec3 a = v[i] - v[0], b = v[(i + 1) % v.size()] - v[0];
        n += glm::cross(a, b);
        extent = glm::max(extent, glm::abs(a));
    }
    double len = glm::length(n), size = glm::length(extent);
    if (!(len > 1e-12 * size * size) || !std::isfinite(len)) {
        why = "zero area";
        return std::nullopt;
    }
    Polygon poly;
    poly.normal = n / len;
    poly.area = 0.5 * len;
    poly.planeOffset = glm::dot(poly.normal, v[0]);
    poly.vertices = std::move(v);
    return poly;
}

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Constraints may touch (seams, shared vertices) but not cross: a crossing would construct a new vertex, which
// throws (and has no index into the polygon).
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds,
                                                       CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Point2 = Kernel::Point_2;

// The axis along which the normal is largest.
int dominantAxis(const dvec3& n) {
    dvec3 a = glm::abs(n);
    return a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
}

// The polygon's vertices in 2-D, dropping the coordinate along which the normal is largest.
std::vector<Point2> project(const Polygon& poly) {
    int drop = dominantAxis(poly.normal);
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    std::vector<Point2> pts;
    for (const dvec3& p : poly.vertices) pts.emplace_back(p[u] - poly.vertices[0][u], p[w] - poly.vertices[0][w]);
    return pts;
}

// Even-odd rule: a seam edge walked twice cancels itself, so holes cut by seams come out right.
bool inside(const std::vector<Point2>& pts, double x, double y) {
    bool in = false;
    for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        double xi = pts[i].x(), yi = pts[i].y(), xj = pts[j].x(), yj = pts[j].y();
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
    }
    return in;
}

bool isConvex(const Polygon& poly) {
    const auto& v = poly.vertices;
    for (size_t i = 0; i < v.size(); ++i) {
        dvec3 e0 = v[(i + 1) % v.size()] - v[i], e1 = v[(i + 2) % v.size()] - v[(i + 1) % v.size()];
        if (glm::dot(glm::cross(e0, e1), poly.normal) < 0) return false;
    }
    return true;
}

// A convex polygon cut into ears as Radiance's polyTriangulate cuts it, so that .obj faces split along the
// diagonals obj2mesh chooses: the outline taken counter-clockwise about the normal's dominant axis, the first
// ear at its last corner, each next ear starting at the corner after the one just cut off.
std::vector<std::array<int, 3>> convexEars(const Polygon& poly) {
    int n = static_cast<int>(poly.vertices.size());
    bool reversed = poly.normal[dominantAxis(poly.normal)] < 0;
    std::vector<int> ring(n);
    for (int i = 0; i < n; ++i) ring[i] = reversed ? n - 1 - i : i;
    std::vector<std::array<int, 3>> tris;
    for (size_t at = ring.size() - 1; ring.size() > 2;) {
        size_t a = at % ring.size(), b = (a + 1) % ring.size(), c = (b + 1) % ring.size();
        tris.push_back({ring[a], ring[b], ring[c]});
        ring.erase(ring.begin() + b);
        at = b;
    }
    return tris;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate(const Polygon& poly) {
    std::vector<std::array<int, 3>> tris;
    int n = static_cast<int>(poly.vertices.size());
    if (isConvex(poly)) return convexEars(poly);
    std::vector<Point2> pts = project(poly);
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handles;
    for (int i = 0; i < n; ++i) {
        handles.push_back(cdt.insert(pts[i]));
        handles.back()->info() = i;
    }
    try {
        for (int i = 0; i < n; ++i)
            if (handles[i] != handles[(i + 1) % n]) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
    } catch (const Cdt::Intersection_of_constraints_exception&) {
        return {};
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        Point2 a = f->vertex(0)->point(), b = f->vertex(1)->point(), c = f->vertex(2)->point();
        if (inside(pts, (a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3))
            tris.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    }
    return tris;
}

double projectedSolidAngle(const std::vector<dvec3>& vertices, const dvec3& p, const dvec3& n) {
    // Clipping adds at most one vertex per edge crossing the plane: twice the vertices bound the outline.
    constexpr size_t kOnStack = 16;
    dvec3 onStack[2 * kOnStack];
    std::vector<dvec3> onHeap(vertices.size() > kOnStack ? 2 * vertices.size() : 0);
    dvec3* clipped = onHeap.empty() ? onStack : onHeap.data();
    size_t count = 0;
    for (size_t i = 0; i < vertices.size(); ++i) {
        dvec3 a = vertices[i] - p, b = vertices[(i + 1) % vertices.size()] - p;
        double ha = glm::dot(a, n), hb = glm::dot(b, n);
        if (ha >= 0) clipped[count++] = a;
        if ((ha >= 0) != (hb >= 0)) clipped[count++] = a + (b - a) * (ha / (ha - hb));
    }
    // Each edge's angle and its plane's unit normal do not depend on the lengths of a and b: no normalizing.
    double sum = 0;
    for (size_t i = 0; i < count; ++i) {
        const dvec3 &a = clipped[i], &b = clipped[(i + 1) % count];
        dvec3 c = glm::cross(a, b);
        double len = glm::length(c);
        if (len > 0) sum += std::atan2(len, glm::dot(a, b)) * glm::dot(n, c) / len;
    }
    return 0.5 * std::abs(sum);
}

}  // namespace brume
