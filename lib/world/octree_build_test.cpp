#include "world/octree_build.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>

#include "scene/octree.h"
#include "scene/placed_files.h"
#include "scene/reader.h"
#include "scoped_directory.h"
#include "world/scene_surfaces.h"

using namespace brume;

namespace {

constexpr double kPi = std::numbers::pi;
const std::string kData = std::string(BRUME_TEST_DATA);

Scene sceneOf(const std::string& text) {
    Scene scene;
    std::istringstream in(text);
    readSceneText(scene, in, "t.rad");
    loadPlacedFiles(scene);
    return scene;
}

// The leaf of `octree` holding point p, found by walking its pre-order nodes; null outside the cube.
class Walker {
public:
    explicit Walker(const BuiltOctree& octree) : octree_(octree), ends_(octree.nodes.size()) { measure(0); }

    const OctreeNode* leafAt(const glm::dvec3& p) const {
        glm::dvec3 origin(octree_.cube.origin[0], octree_.cube.origin[1], octree_.cube.origin[2]);
        double size = octree_.cube.size;
        for (int a = 0; a < 3; ++a)
            if (p[a] < origin[a] || p[a] > origin[a] + size) return nullptr;
        size_t node = 0;
        while (octree_.nodes[node].tree) {
            size /= 2;
            int child = 0;
            for (int a = 0; a < 3; ++a)
                if (p[a] >= origin[a] + size) child |= 1 << a, origin[a] += size;
            node += 1;
            for (int c = 0; c < child; ++c) node = ends_[node];
        }
        return &octree_.nodes[node];
    }

private:
    // The index after node i's subtree.
    size_t measure(size_t i) {
        size_t next = i + 1;
        if (octree_.nodes[i].tree)
            for (int c = 0; c < 8; ++c) next = measure(next);
        return ends_[i] = next;
    }

    const BuiltOctree& octree_;
    std::vector<size_t> ends_;
};

glm::dvec3 perpendicular(const glm::dvec3& n) {
    glm::dvec3 t = std::abs(n.x) < .9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(n, t));
}

// Points spread over each surface object of the scene.
std::vector<std::pair<int, glm::dvec3>> pointsOn(const Scene& scene, int perSurface, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<std::pair<int, glm::dvec3>> points;
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        if (!isSurfaceType(scene.objects[i].type)) continue;
        Surface s = *makeSurface(scene, i);
        for (int k = 0; k < perSurface; ++k) {
            glm::dvec3 p;
            if (auto* poly = std::get_if<Polygon>(&s.shape)) {
                auto [a, b, c] = poly->triangles[size_t(u(rng) * double(poly->triangles.size()))];
                double r1 = std::sqrt(u(rng)), r2 = u(rng);
                p = (1 - r1) * poly->vertices[a] + r1 * (1 - r2) * poly->vertices[b] + r1 * r2 * poly->vertices[c];
            } else if (auto* sphere = std::get_if<Sphere>(&s.shape)) {
                double z = 2 * u(rng) - 1, phi = 2 * kPi * u(rng), r = std::sqrt(1 - z * z);
                p = sphere->center + sphere->radius * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
            } else if (auto* cone = std::get_if<Cone>(&s.shape)) {
                glm::dvec3 axis = glm::normalize(cone->top - cone->base), x = perpendicular(axis), y = glm::cross(axis, x);
                double t = u(rng), phi = 2 * kPi * u(rng), r = cone->baseRadius + t * (cone->topRadius - cone->baseRadius);
                p = cone->base + t * (cone->top - cone->base) + r * (std::cos(phi) * x + std::sin(phi) * y);
            } else if (auto* ring = std::get_if<Ring>(&s.shape)) {
                glm::dvec3 x = perpendicular(ring->normal), y = glm::cross(ring->normal, x);
                double r = ring->innerRadius + u(rng) * (ring->outerRadius - ring->innerRadius), phi = 2 * kPi * u(rng);
                p = ring->center + r * (std::cos(phi) * x + std::sin(phi) * y);
            }
            points.emplace_back(i, p);
        }
    }
    return points;
}

// Random triangles, spheres, bubbles, cones, cylinders, cups, tubes and rings in a 10 m box.
std::string clutter(int count, std::mt19937& rng) {
    std::uniform_real_distribution<double> at(-5, 5), size(.05, 1.5);
    std::ostringstream s;
    s.precision(17);
    s << "void plastic m 0 0 5 .5 .5 .5 0 0\n";
    const char* const types[] = {"polygon", "sphere", "bubble", "cone", "cylinder", "cup", "tube", "ring"};
    for (int i = 0; i < count; ++i) {
        std::string type = types[i % 8];
        glm::dvec3 c(at(rng), at(rng), at(rng)), d(at(rng), at(rng), at(rng));
        d = glm::normalize(d) * size(rng);
        double r = size(rng) / 3;
        s << "m " << type << " o" << i << " 0 0 ";
        if (type == "polygon") {
            glm::dvec3 e(at(rng), at(rng), at(rng));
            glm::dvec3 b = c + d, t = c + glm::normalize(e) * size(rng);
            s << "9 " << c.x << ' ' << c.y << ' ' << c.z << ' ' << b.x << ' ' << b.y << ' ' << b.z << ' ' << t.x << ' '
              << t.y << ' ' << t.z << '\n';
        } else if (type == "sphere" || type == "bubble") {
            s << "4 " << c.x << ' ' << c.y << ' ' << c.z << ' ' << r << '\n';
        } else if (type == "ring") {
            s << "8 " << c.x << ' ' << c.y << ' ' << c.z << ' ' << d.x << ' ' << d.y << ' ' << d.z << ' ' << r / 3 << ' '
              << r << '\n';
        } else {
            glm::dvec3 t = c + d;
            bool cylinder = type == "cylinder" || type == "tube";
            s << (cylinder ? 7 : 8) << ' ' << c.x << ' ' << c.y << ' ' << c.z << ' ' << t.x << ' ' << t.y << ' ' << t.z
              << ' ' << r;
            if (!cylinder) s << ' ' << r / 2;
            s << '\n';
        }
    }
    return s.str();
}

bool lists(const OctreeNode* leaf, int object) {
    return leaf && std::find(leaf->set.begin(), leaf->set.end(), object) != leaf->set.end();
}

// The property the octree's users rely on: a ray meets a surface only in cubes that list it. Radiance's
// rtrace, given an octree missing a surface from a cube it crosses, sees through it there.
TEST(OctreeBuild, EveryPointOfEverySurfaceLiesInALeafListingIt) {
    std::mt19937 rng(7);
    Scene scene = sceneOf(clutter(400, rng));
    OctreeBuildOptions options;
    options.objectLimit = 3;
    options.resolution = 1024;
    BuiltOctree octree = buildOctree(scene, scene.objects.size(), options);
    ASSERT_GT(octree.nodes.size(), 500u);  // divided well below the root
    Walker walker(octree);
    int missing = 0;
    for (const auto& [object, p] : pointsOn(scene, 400, rng))
        if (!lists(walker.leafAt(p), object)) ++missing;
    EXPECT_EQ(missing, 0);
    EXPECT_EQ(octree.overflowObject, -1);
}

// Loose tests list objects where they are not; how many is a matter of speed for the tracer, but a leaf
// listing everything would be useless: on this clutter, leaves list few objects.
TEST(OctreeBuild, LeavesListFewObjects) {
    std::mt19937 rng(8);
    Scene scene = sceneOf(clutter(400, rng));
    BuiltOctree octree = buildOctree(scene, scene.objects.size());
    size_t leaves = 0, listed = 0, largest = 0;
    for (const OctreeNode& n : octree.nodes)
        if (!n.tree && !n.set.empty()) ++leaves, listed += n.set.size(), largest = std::max(largest, n.set.size());
    EXPECT_LT(double(listed) / double(leaves), 6.0);
    EXPECT_LT(largest, 40u);
}

std::string cubeText(const OctreeCube& c) {
    char s[200];
    std::snprintf(s, sizeof s, "%.12g %.12g %.12g %.12g", c.origin[0], c.origin[1], c.origin[2], c.size);
    return s;
}

// The cube decides rtrace's scale (-ar): Brume's octrees must have the one Radiance's oconv gives. Radiance
// 6.1's oconv made scene_frozen.oct from scene.rad (every surface type, test/data/scene/README.md) and
// placed.oct from placed.rad (an instance of it and compiled meshes, rotated and scaled).
TEST(OctreeBuild, TheCubeIsRadiancesOconvs) {
    // Instances name their files relative to the current directory, as oconv ran there.
    brume_test::ScopedDirectory here(kData + "/scene");
    for (const std::string name : {"scene", "placed"}) {
        SCOPED_TRACE(name);
        Scene text;
        readSceneFile(text, name + ".rad");
        size_t count = text.objects.size();
        loadPlacedFiles(text);
        Scene radiance;
        readOctreeFile(radiance, name + (name == "scene" ? "_frozen" : "") + ".oct");
        EXPECT_EQ(cubeText(buildOctree(text, count).cube), cubeText(*radiance.cube));
    }
}

// A torus of 32 cones (what Radiance's genrev makes): their boxes overlap everywhere along the ring, but
// the cones themselves meet few cubes.
TEST(OctreeBuild, ConesTouchingEndToEndDoNotDivideWithoutEnd) {
    std::ostringstream s;
    s << "void plastic m 0 0 5 .5 .5 .5 0 0\n";
    for (int i = 0; i < 32; ++i) {
        double a0 = 2 * kPi * i / 32, a1 = 2 * kPi * (i + 1) / 32;
        s << "m cone c" << i << " 0 0 8 " << 2 * std::cos(a0) << " 0 " << std::sin(a0) << " " << 2 * std::cos(a1) << " 0 "
          << std::sin(a1) << " " << 2 + std::cos(a0) << " " << 2 + std::cos(a1) << "\n";
    }
    Scene scene = sceneOf(s.str());
    BuiltOctree octree = buildOctree(scene, scene.objects.size());
    EXPECT_LT(octree.nodes.size(), 200000u);
}

// Where more objects than the limit meet everywhere (coincident spheres), dividing gains nothing.
TEST(OctreeBuild, ObjectsThatMeetEveryChildStayInOneLeaf) {
    std::string text = "void plastic m 0 0 5 .5 .5 .5 0 0\n";
    for (int i = 0; i < 10; ++i) text += "m polygon p" + std::to_string(i) + " 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n";
    Scene scene = sceneOf(text);
    BuiltOctree octree = buildOctree(scene, scene.objects.size());
    // The flat cube's children above and below the plane miss them all, the ones on it meet them all.
    EXPECT_LT(octree.nodes.size(), 50000u);
    Walker walker(octree);
    const OctreeNode* leaf = walker.leafAt({.5, .5, 0});
    ASSERT_NE(leaf, nullptr);
    EXPECT_EQ(leaf->set.size(), 10u);
}

TEST(OctreeBuild, ModifiersAndSourcesTakeNoPlace) {
    Scene scene = sceneOf(
        "void glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 5\n"
        "void plastic m 0 0 5 .5 .5 .5 0 0\nm sphere ball 0 0 4 1 2 3 .5\n");
    BuiltOctree octree = buildOctree(scene, scene.objects.size());
    ASSERT_EQ(octree.nodes.size(), 1u);
    EXPECT_EQ(octree.nodes[0].set, std::vector<int>{3});
    EXPECT_NEAR(octree.cube.size, 1 + 2e-5, 1e-12);
}

TEST(OctreeBuild, AGivenCubeMustHoldTheScene) {
    Scene scene = sceneOf("void plastic m 0 0 5 .5 .5 .5 0 0\nm sphere ball 0 0 4 1 2 3 .5\n");
    OctreeBuildOptions options;
    options.cube = OctreeCube{{0, 0, 0}, 4};
    EXPECT_EQ(buildOctree(scene, scene.objects.size(), options).cube.size, 4);
    options.cube = OctreeCube{{0, 0, 0}, 3};  // the ball reaches z = 3.5
    try {
        buildOctree(scene, scene.objects.size(), options);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("t.rad:2: boundary does not encompass scene"), std::string::npos) << e.what();
    }
}

}  // namespace
