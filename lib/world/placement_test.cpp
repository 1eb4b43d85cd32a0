// Surfaces placed by instances and meshes keep the exactness of the scene's own: hits computed in double
// precision in the prototype's coordinates, and rays never meeting the surface they leave, at any scale.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "sampling/random.h"
#include "scene/reader.h"
#include "world/scene_geometry.h"
#include "world/scene_surfaces.h"

using namespace brume;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The unit box's floor, a ball and a post (as scene_geometry_test.cpp's, unscaled).
std::vector<Surface> boxSurfaces(Scene& scene) {
    std::istringstream in(
        "void plastic p 0 0 5 .5 .5 .5 0 0\n"
        "p polygon floor 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n"
        "p sphere ball 0 0 4 .5 .5 .5 .2\n"
        "p cylinder post 0 0 7 .8 .8 0 .8 .8 1 .05\n");
    readSceneText(scene, in, "t.rad");
    std::vector<Surface> out;
    for (int i = 1; i < int(scene.objects.size()); ++i) out.push_back(*makeSurface(scene, i));
    return out;
}

// The inside of the unit cube as a mesh of 12 triangles facing inward.
Mesh cubeMesh() {
    Mesh m;
    for (int i = 0; i < 8; ++i) m.vertices.push_back(dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            auto corner = [&](int a, int b) { return uint32_t(side << axis | a << u | b << v); };
            std::array<uint32_t, 4> q{corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
            if (side == 1) std::swap(q[1], q[3]);  // counter-clockwise seen from inside
            m.triangles.push_back({q[0], q[1], q[2]});
            m.triangles.push_back({q[0], q[2], q[3]});
        }
    }
    m.materials.assign(m.triangles.size(), 0);
    return m;
}

std::string number(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

// Rotated, scaled by k, mirrored or not, and moved 3k to 5k away from the origin.
Transform placement(double k, bool mirror) {
    std::vector<std::string> args{"-rz", "30", "-ry", "10", "-s", number(k)};
    if (mirror) args.push_back("-mx");
    args.insert(args.end(), {"-t", number(3 * k), number(-4 * k), number(5 * k)});
    return parseTransform(args).transform;
}

SceneLayout placed(std::vector<Surface> surfaces, const Mesh* mesh, const Transform& t) {
    SceneLayout layout;
    layout.prototypes.push_back(Prototype{0, int(surfaces.size()), mesh});
    layout.surfaces = std::move(surfaces);
    layout.placements.push_back(Placement{0, t, t.inverse(), 0, 0, t});  // with a modifier: all visible
    return layout;
}

}  // namespace

TEST(Placement, TransformsArePlacedAsRadianceXform) {
    Transform t = placement(2, false);
    // -rz 30 -ry 10 -s 2 -t 6 -8 10, the first applied first.
    EXPECT_NEAR(glm::length(t.point(dvec3(0)) - dvec3(6, -8, 10)), 0, 1e-12);
    EXPECT_NEAR(glm::length(t.vector(dvec3(0, 0, 1))), 2, 1e-12);
    EXPECT_TRUE(placement(2, true).mirrors());
}

// As scene_geometry_test.cpp's RaysLeaveSurfacesCleanlyAtTinyAndHugeScales, through a placement.
TEST(Placement, RaysLeavePlacedSurfacesCleanlyAtTinyAndHugeScales) {
    for (double k : {1e-6, 1.0, 1e6}) {
        for (bool mirror : {false, true}) {
            Scene scene;
            Transform t = placement(k, mirror);
            SceneGeometry g(placed(boxSurfaces(scene), nullptr, t));
            auto world = [&](const dvec3& o, const dvec3& d, SurfaceId from = {}) {
                return g.intersect(Ray{t.point(o), glm::normalize(t.vector(d)), kInf, from});
            };
            auto ball = world(dvec3(0.5, 0.5, 0.9), dvec3(0, 0, -1));
            ASSERT_TRUE(ball) << k;
            EXPECT_NEAR(ball->t, 0.2 * k, 1e-9 * k);
            EXPECT_EQ(ball->surface.instance, 0);
            // The hit's normal is the ball's, turned with the placement.
            EXPECT_NEAR(glm::dot(ball->normal, glm::normalize(t.vector(dvec3(0, 0, 1)))), 1, 1e-12);
            EXPECT_FALSE(g.intersect(Ray{ball->point, glm::normalize(t.vector(dvec3(0, 0, 1))), kInf, ball->surface}));
            auto floor = world(dvec3(0.3, 0.2, 0.5), dvec3(0, 0, -1));
            ASSERT_TRUE(floor);
            // On the floor's plane to rounding, in the prototype's coordinates.
            EXPECT_LT(std::abs(t.inverse().point(floor->point).z), 1e-13);
            for (int i = 0; i < 64; ++i) {
                double a = i * 0.098;
                dvec3 d = glm::normalize(t.vector(dvec3(std::cos(a), std::sin(a), 1e-7)));
                auto again = g.intersect(Ray{floor->point, d, kInf, floor->surface});
                EXPECT_TRUE(!again || again->surface != floor->surface) << "scale " << k;
            }
        }
    }
}

// Rays bouncing inside a placed mesh cube, often leaving from its edges and diagonals, always meet another
// face, on the cube to rounding: never the triangle they leave, nor its neighbours where they start.
TEST(Placement, RaysBouncingInsideAPlacedMeshNeverMeetTheirStart) {
    Mesh cube = cubeMesh();
    for (double k : {1e-6, 1.0, 1e6}) {
        for (bool mirror : {false, true}) {
            Transform t = placement(k, mirror), inverse = t.inverse();
            SceneGeometry g(placed({}, &cube, t));
            Random rng(7, 0);
            Ray ray{t.point(dvec3(0.5, 0.5, 0.5)), glm::normalize(t.vector(dvec3(1, 1, 1)))};  // at a corner
            for (int bounce = 0; bounce < 2000; ++bounce) {
                auto hit = g.intersect(ray);
                ASSERT_TRUE(hit) << "k " << k << " bounce " << bounce;
                dvec3 p = inverse.point(hit->point);
                double wall = std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(1 - p.x),
                                        std::abs(1 - p.y), std::abs(1 - p.z)});
                EXPECT_LT(wall, 1e-12) << "k " << k << " bounce " << bounce;
                EXPECT_GT(hit->t, 1e-6 * k) << "k " << k << " bounce " << bounce;
                // The next direction: into the cube from every wall the ray starts on; every other bounce toward
                // a point on one of the cube's edges (so that the next ray starts on an edge), unless that edge
                // lies in a wall the ray starts on.
                dvec3 local = dvec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5;
                dvec3 edge(rng.uniform());
                int axis = bounce % 3;
                edge[(axis + 1) % 3] = rng.uniform() < 0.5 ? 0 : 1, edge[(axis + 2) % 3] = rng.uniform() < 0.5 ? 0 : 1;
                bool towardEdge = bounce % 2 == 0;
                for (int c = 0; c < 3; ++c) {
                    bool onWall = std::abs(p[c]) < 1e-9 || std::abs(1 - p[c]) < 1e-9;
                    if (onWall) local[c] = std::abs(local[c]) * (p[c] < 0.5 ? 1 : -1);
                    towardEdge = towardEdge && !(onWall && std::abs(edge[c] - p[c]) < 0.5);
                }
                if (towardEdge) local = edge - p;
                dvec3 d = glm::normalize(t.vector(local));
                ray = Ray{hit->point, d, kInf, hit->surface};
            }
        }
    }
}

namespace {

// A tilted terrain z = 0.05 x + 0.03 y as a mesh of cells × cells squares of `cell` metres (two triangles
// each) about its centre.
Mesh terrain(int cells, double cell) {
    Mesh m;
    double half = 0.5 * cells * cell;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            double x = i * cell - half, y = j * cell - half;
            m.vertices.push_back(dvec3(x, y, 0.05 * x + 0.03 * y));
        }
    auto at = [&](int i, int j) { return uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    m.materials.assign(m.triangles.size(), 0);
    return m;
}

}  // namespace

// A terrain mesh placed at a site's UTM coordinates under a model, as a 20 km grid of 200 m cells and as two
// triangles 4000 km wide (exact shapes then, being huge beside the model): from points 1 mm and 0.1 mm above
// it, and right on it, rays down meet it at exactly that height; rays up leave it. Also 5 km from the model.
TEST(Placement, TerrainMeshesAtSiteCoordinatesAreMetExactly) {
    Scene scene;
    std::vector<Surface> model = boxSurfaces(scene);
    const dvec3 site(512345.6, 5412345.7, 120);
    for (const Mesh& mesh : {terrain(100, 200), terrain(1, 4e6)}) {
        SceneLayout layout;
        layout.surfaces = model;
        for (Surface& s : layout.surfaces) s.shape = transformed(s.shape, parseTransform(std::vector<std::string>{
                                                                            "-t", "512345.6", "5412345.7", "125"}).transform);
        layout.ownSurfaces = int(layout.surfaces.size());
        layout.prototypes.push_back(Prototype{layout.ownSurfaces, layout.ownSurfaces, &mesh});
        Transform t = parseTransform(std::vector<std::string>{"-t", "512345.6", "5412345.7", "120"}).transform;
        layout.placements.push_back(Placement{0, t, t.inverse(), 0, 0, t});
        SceneGeometry g(std::move(layout));
        for (dvec3 p : {dvec3(0.3, 0.2, 0), dvec3(5000, -3000, 0), dvec3(-17.1, 41.3, 0)}) {
            p.z = 0.05 * p.x + 0.03 * p.y;
            for (double h : {1e-3, 1e-4, 0.0}) {
                Ray down{site + p + dvec3(0, 0, h), dvec3(0, 0, -1)};
                down.tmin = 0;
                auto hit = g.intersect(down);
                if (h == 0) {  // right on it: it, or nothing, is met at once
                    EXPECT_TRUE(!hit || hit->t < 1e-9) << p.x;
                    continue;
                }
                ASSERT_TRUE(hit) << p.x << " " << h;
                EXPECT_NEAR(hit->t, h, 1e-9) << p.x << " " << h;
                EXPECT_EQ(hit->surface.instance, 0);
                Ray up{hit->point, glm::normalize(dvec3(0.2, -0.1, 1)), kInf, hit->surface};
                auto again = g.intersect(up);
                EXPECT_TRUE(!again || again->surface.instance < 0) << p.x << " " << h;
            }
        }
    }
}
