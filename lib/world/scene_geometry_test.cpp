#include "world/scene_geometry.h"

#include <gtest/gtest.h>

#include <sstream>

#include "geometry/polygon.h"
#include "scene/reader.h"
#include "world/scene_surfaces.h"

using namespace brume;

namespace {

std::vector<Surface> surfacesOf(const std::string& text, Scene& scene) {
    std::istringstream in(text);
    readSceneText(scene, in, "t.rad");
    std::vector<Surface> out;
    for (int i = 0; i < int(scene.objects.size()); ++i)
        if (isSurfaceType(scene.objects[i].type))
            if (auto s = makeSurface(scene, i)) out.push_back(std::move(*s));
    return out;
}

// A unit box of polygons facing inward, a sphere and a cylinder inside, all scaled by `k`.
std::string box(double k) {
    auto v = [k](double x) {
        std::ostringstream o;
        o.precision(17);
        o << x * k;
        return o.str();
    };
    std::string s = "void plastic p 0 0 5 .5 .5 .5 0 0\n";
    s += "p polygon floor 0 0 12 " + v(0) + " " + v(0) + " " + v(0) + " " + v(1) + " " + v(0) + " " + v(0) + " " +
         v(1) + " " + v(1) + " " + v(0) + " " + v(0) + " " + v(1) + " " + v(0) + "\n";
    s += "p sphere ball 0 0 4 " + v(0.5) + " " + v(0.5) + " " + v(0.5) + " " + v(0.2) + "\n";
    s += "p cylinder post 0 0 7 " + v(0.8) + " " + v(0.8) + " " + v(0) + " " + v(0.8) + " " + v(0.8) + " " + v(1) +
         " " + v(0.05) + "\n";
    return s;
}

}  // namespace

// Rays leaving a surface never hit it again at their origin, at any scene scale (no fixed epsilon).
TEST(SceneGeometry, RaysLeaveSurfacesCleanlyAtTinyAndHugeScales) {
    for (double k : {1e-6, 1.0, 1e6}) {
        Scene scene;
        SceneGeometry g(surfacesOf(box(k), scene));
        // Down onto the sphere's top, then straight back up: must escape, not re-hit the sphere.
        auto hit = g.intersect(Ray{dvec3(0.5, 0.5, 0.9) * k, dvec3(0, 0, -1)});
        ASSERT_TRUE(hit) << k;
        EXPECT_NEAR(hit->t, 0.2 * k, 1e-9 * k);
        EXPECT_FALSE(g.intersect(Ray{hit->point, dvec3(0, 0, 1), std::numeric_limits<double>::infinity(), hit->surface}))
            << "scale " << k;
        // Grazing departures from the floor, in many directions: never the floor again.
        auto floor = g.intersect(Ray{dvec3(0.3, 0.2, 0.5) * k, dvec3(0, 0, -1)});
        ASSERT_TRUE(floor);
        for (int i = 0; i < 64; ++i) {
            double a = i * 0.098;
            dvec3 d = glm::normalize(dvec3(std::cos(a), std::sin(a), 1e-7));
            auto again = g.intersect(Ray{floor->point, d, std::numeric_limits<double>::infinity(), floor->surface});
            EXPECT_TRUE(!again || again->surface != floor->surface) << "scale " << k;
        }
        // From inside the sphere (entering through its bottom), the far side is found at the right place.
        auto inside = g.intersect(Ray{dvec3(0.5, 0.5, 0.1) * k, dvec3(0, 0, 1)});
        ASSERT_TRUE(inside);
        auto far = g.intersect(Ray{inside->point, dvec3(0, 0, 1), std::numeric_limits<double>::infinity(), inside->surface});
        ASSERT_TRUE(far);
        EXPECT_NEAR(far->t, 0.4 * k, 1e-9 * k);
        EXPECT_EQ(far->surface, inside->surface);
    }
}

TEST(SceneGeometry, CylinderIsExactNotTessellated) {
    Scene scene;
    SceneGeometry g(surfacesOf(box(1), scene));
    // Toward the post's axis: the hit lies exactly at its radius.
    auto hit = g.intersect(Ray{dvec3(0.5, 0.8, 0.5), dvec3(1, 0, 0)});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 0.25, 1e-12);
    EXPECT_NEAR(hit->normal.x, -1, 1e-12);
}

TEST(Polygon, ConcavePolygonsAreTriangulatedInside) {
    // An L shape: its area is 3, and the notch (1.5, 1.5) is outside.
    std::string why;
    auto p = makePolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, why);
    ASSERT_TRUE(p);
    EXPECT_DOUBLE_EQ(p->area, 3);
    auto tris = triangulate(*p);
    double area = 0;
    for (const auto& t : tris)
        area += 0.5 * glm::length(glm::cross(p->vertices[t[1]] - p->vertices[t[0]], p->vertices[t[2]] - p->vertices[t[0]]));
    EXPECT_NEAR(area, 3, 1e-12);
}

TEST(Polygon, DegeneratePolygonsAreRefusedWithAReason) {
    std::string why;
    EXPECT_FALSE(makePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, why));
    EXPECT_EQ(why, "zero area");
    EXPECT_FALSE(makePolygon({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, why));
    EXPECT_EQ(why, "fewer than 3 distinct vertices");
}

// Radiance turns surfaces with negative radii inside out (with a warning) and refuses radii of opposite signs.
TEST(SceneGeometry, NegativeRadiiTurnSurfacesInsideOutAsRadiance) {
    Scene scene;
    auto s = surfacesOf("void plastic p 0 0 5 .5 .5 .5 0 0\n"
                        "p sphere a 0 0 4 0 0 0 -2\n"
                        "p bubble b 0 0 4 0 0 0 -2\n"
                        "p cylinder c 0 0 7 0 0 0 0 0 1 -1\n"
                        "p cone d 0 0 8 0 0 0 0 0 1 -1 -.5\n",
                        scene);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_TRUE(std::get<Sphere>(s[0].shape).inward);
    EXPECT_EQ(std::get<Sphere>(s[0].shape).radius, 2);
    EXPECT_FALSE(std::get<Sphere>(s[1].shape).inward);
    EXPECT_TRUE(std::get<Cone>(s[2].shape).inward);
    EXPECT_TRUE(std::get<Cone>(s[3].shape).inward);
    EXPECT_EQ(std::get<Cone>(s[3].shape).topRadius, .5);
    Scene bad;
    EXPECT_THROW(surfacesOf("void plastic p 0 0 5 .5 .5 .5 0 0\np cone d 0 0 8 0 0 0 0 0 1 -1 1\n", bad), Error);
}

namespace {

// Every surface blocks shadow rays but the one named.
struct AllBlockBut : ShadowBlockers {
    int passing = -1;
    bool decide = true;
    bool blocksShadows(const SurfaceId& id) const override { return id.surface != passing; }
    bool blockersDecide() const override { return decide; }
};

}  // namespace

// Occlusion queries see only what lies before the target: the target itself near its end is no obstacle,
// anything the caller does not call a blocker, or the target met early, leaves the answer to the walk.
TEST(SceneGeometry, OcclusionJudgesWhatLiesBeforeTheTarget) {
    for (double k : {1e-6, 1.0, 1e6}) {
        Scene scene;
        SceneGeometry g(surfacesOf(box(k), scene));
        const SurfaceId floor{0}, ball{1};
        AllBlockBut blockers;
        Ray up{dvec3(0.5, 0.5, 0) * k, dvec3(0, 0, 1), std::numeric_limits<double>::infinity(), floor};
        EXPECT_EQ(g.occlusion(up, ball, 0.3 * k, blockers), Occlusion::Clear) << k;
        EXPECT_EQ(g.occlusion(up, ball, 0.7 * k, blockers), Occlusion::Unsure) << k;  // the ball met early
        EXPECT_EQ(g.occlusion(up, SurfaceId{}, std::numeric_limits<double>::infinity(), blockers), Occlusion::Blocked);
        blockers.passing = 1;
        EXPECT_EQ(g.occlusion(up, SurfaceId{}, std::numeric_limits<double>::infinity(), blockers), Occlusion::Unsure);
        // Down onto the floor (triangles): the target at the end is no obstacle; the floor short of the end
        // blocks, the floor within rounding of it is left to the walk.
        Ray down{dvec3(0.2, 0.2, 0.9) * k, dvec3(0, 0, -1)};
        EXPECT_EQ(g.occlusion(down, floor, 0.9 * k, blockers), Occlusion::Clear) << k;
        EXPECT_EQ(g.occlusion(down, SurfaceId{}, 0.95 * k, blockers), Occlusion::Blocked) << k;
        EXPECT_EQ(g.occlusion(down, SurfaceId{}, 0.9 * k, blockers), Occlusion::Unsure) << k;
        // Toward a point short of the ball: nothing in the way.
        EXPECT_EQ(g.occlusion(up, SurfaceId{}, 0.25 * k, blockers), Occlusion::Clear) << k;
        // Past the post, a blocker, to a target beyond it.
        Ray across{dvec3(0.5, 0.8, 0) * k, glm::normalize(dvec3(1, 0, 0.1)), std::numeric_limits<double>::infinity(), floor};
        EXPECT_EQ(g.occlusion(across, ball, 0.5 * k, blockers), Occlusion::Blocked) << k;
        // Through the ball, which passes light, to the post behind it: blocked, unless what lies before a
        // blocker may matter.
        Ray through{dvec3(0.2, 0.2, 0.5) * k, glm::normalize(dvec3(1, 1, 0))};
        EXPECT_EQ(g.occlusion(through, SurfaceId{}, std::numeric_limits<double>::infinity(), blockers), Occlusion::Blocked);
        blockers.decide = false;
        EXPECT_EQ(g.occlusion(through, SurfaceId{}, std::numeric_limits<double>::infinity(), blockers), Occlusion::Unsure);
        EXPECT_EQ(g.occlusion(across, ball, 0.5 * k, blockers), Occlusion::Unsure) << k;
    }
}
