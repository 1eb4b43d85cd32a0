// Instances and meshes against the same surfaces given one by one: placed, an octree or a mesh must light and
// be lit exactly as the polygons, spheres, rings and cylinders Radiance's xform writes for the same transform,
// with Radiance's modifier rules.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "scene_text.h"
#include "scoped_directory.h"

using namespace brume;
using namespace brume::test;

namespace {

const std::string kDir = std::string(BRUME_TEST_DATA) + "/instance/";

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

const char* kFloor =
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "grey polygon floor 0 0 12 -10 -10 -1.05  10 -10 -1.05  10 10 -1.05  -10 10 -1.05\n";

// Relative difference of two spectra's first channels (both near zero agree).
double relative(const Spectrum& a, const Spectrum& b) {
    double scale = std::max(std::abs(a[0]), std::abs(b[0]));
    return scale < 1e-12 ? 0.0 : std::abs(a[0] - b[0]) / scale;
}

// A scene with a temporary file beside it (for meshes given as .obj text).
struct TempFile {
    std::filesystem::path path;
    TempFile(const std::string& name, const std::string& text)
        : path(std::filesystem::temp_directory_path() / ("brume_" + std::to_string(getpid()) + "_" + name)) {
        std::ofstream(path) << text;
    }
    ~TempFile() { std::filesystem::remove(path); }
};

// Irradiance where a ray straight down meets the floor (rtrace -i), a deterministic closed form there.
double floorIrradiance(const Integrator& integrator, double x, double y, uint64_t index) {
    return test::irradianceAtHit(integrator, dvec3(x, y, 1), dvec3(0, 0, -1), index).value[0];
}

}  // namespace

// lamp.oct holds a light panel over a shelf, a ball, a disc and a post; lamp_N.rad are those objects moved by
// xform with the N-th line of transforms.txt (translated, rotated, scaled, mirrored, iterated). Placed by an
// instance with the same transform, every view ray and sensor gets the same value: shadows, the light inside
// the instance (a source Brume samples, unlike Radiance) and all. To 1e-8 in distances, as a frozen octree
// stores reals with 31-bit mantissas, and to 1e-6 in values, which are single precision (sensors: see below).
TEST(Instance, PlacedOctreeEqualsTheXformedSurfaces) {
    ScopedRayPath path(kDir.c_str());
    auto transforms = lines(kDir + "transforms.txt");
    ASSERT_EQ(transforms.size(), 4u);
    for (size_t n = 0; n < transforms.size(); ++n) {
        std::vector<std::string> args = words(transforms[n]);
        std::string instance =
            "void instance lamp " + std::to_string(args.size() + 1) + " lamp.oct " + transforms[n] + "\n0\n0\n";
        TestScene placed(kFloor + instance);
        TestScene xformed(kFloor + fileText(kDir + "lamp_" + std::to_string(n + 1) + ".rad"));
        RenderSettings s = fixedSeed();
        s.ambientBounces = 0;
        Integrator a(placed.render, s), b(xformed.render, s);
        Transform t = parseTransform(args).transform;
        // View rays from above onto the shelf, the ball, the disc, the post and the floor around, in the lamp's
        // own coordinates, and sensors on the floor (to 4e-6: a sensor sums 64 shadow rays, each rounded to single
        // precision, up to 64 × 6e-8).
        const dvec3 targets[] = {{.1, .1, .5}, {-.15, -.12, .5}, {.8, 0, .3},   {.85, .05, .25},  {-.8, .25, .01},
                                 {0, .75, .2}, {1.2, 1, 0},      {0, 0, -1.05}, {.7, -.7, -1.05}, {-1.5, .3, -1.05}};
        double lit = 0;  // by the lamp inside the instance
        for (size_t i = 0; i < std::size(targets); ++i) {
            dvec3 p = t.point(targets[i]), up = glm::normalize(t.vector(dvec3(0.1, 0.2, 1)));
            RayRecord ra = test::trace(a, p + 2.0 * up, -up, i), rb = test::trace(b, p + 2.0 * up, -up, i);
            EXPECT_NEAR(ra.firstLength, rb.firstLength, 1e-8 * rb.firstLength) << transforms[n] << " target " << i;
            EXPECT_LT(relative(ra.value, rb.value), 1e-6) << transforms[n] << " target " << i;
            dvec3 floor(p.x, p.y, -1.05);
            Spectrum ea = test::irradiance(a, floor, dvec3(0, 0, 1), i).value;
            EXPECT_LT(relative(ea, test::irradiance(b, floor, dvec3(0, 0, 1), i).value), 4e-6)
                << transforms[n] << " sensor " << i;
            lit += ea[0];
        }
        EXPECT_GT(lit, 1) << transforms[n];
    }
}

// A unit-square light above a floor: the floor as a mesh (from a Wavefront file, split into triangles) or as
// polygons gives the same illuminance, the closed form of the square, to 1e-9.
TEST(Instance, MeshFloorLitAsTheSamePolygons) {
    TempFile obj("floor.obj",
                 "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nv 0 -2 0\nv 0 2 0\n"
                 "f 1 5 6 4\nf 5 2 3 6\n");
    const std::string light =
        "void light lum 0 0 3 100 100 100\n"
        "lum polygon lamp 0 0 12 -.5 -.5 2  -.5 .5 2  .5 .5 2  .5 -.5 2\n"
        "void plastic white 0 0 5 .5 .5 .5 0 0\n";
    TestScene mesh(light + "white mesh floor 1 " + obj.path.string() + "\n0\n0\n");
    TestScene polygons(light +
                       "white polygon a 0 0 12 -2 -2 0  0 -2 0  0 2 0  -2 2 0\n"
                       "white polygon b 0 0 12 0 -2 0  2 -2 0  2 2 0  0 2 0\n");
    Integrator a(mesh.render, fixedSeed()), b(polygons.render, fixedSeed());
    uint64_t index = 0;
    for (double x : {-1.7, -0.3, 0.0, 0.4, 1.9})
        for (double y : {-1.2, 0.1, 0.5}) {
            double e = floorIrradiance(a, x, y, index);
            EXPECT_GT(e, 0);
            EXPECT_NEAR(e, floorIrradiance(b, x, y, index++), 1e-9 * e) << x << " " << y;
        }
}

// Vertex normals, all tilted the same way, shade a flat mesh as a sensor facing that way: Radiance's
// perturbed normal (to 1e-6: a mesh keeps its normals in single precision). Seen from behind, the normal
// turns with the surface.
TEST(Instance, SmoothMeshShadesWithItsInterpolatedNormal) {
    TempFile obj("tilted.obj",
                 "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nvn .3 .1 1\n"
                 "f 1//1 2//1 3//1 4//1\n");
    TestScene t(
        "void light lum 0 0 3 100 100 100\n"
        "lum polygon lamp 0 0 12 -.5 -.5 2  -.5 .5 2  .5 .5 2  .5 -.5 2\n"
        "void plastic white 0 0 5 .5 .5 .5 0 0\n"
        "white mesh floor 1 " +
        obj.path.string() + "\n0\n0\n");
    Integrator integrator(t.render, fixedSeed());
    dvec3 n = glm::normalize(dvec3(.3, .1, 1));
    for (double x : {-1.0, 0.2, 1.5}) {
        RayRecord hit = test::irradianceAtHit(integrator, dvec3(x, 0.3, 1), dvec3(0, 0, -1), 0);
        EXPECT_NEAR(glm::dot(hit.normal, n), 1, 1e-6);  // -on: the perturbed normal
        EXPECT_NEAR(hit.surfaceNormal.z, 1, 1e-12);     // -oN: the triangle's
        double sensor = test::irradiance(integrator, dvec3(x, 0.3, 0), n, 0).value[0];
        EXPECT_NEAR(hit.value[0], sensor, 1e-6 * sensor) << x;
    }
    RayRecord below = test::trace(integrator, dvec3(0.2, 0.3, -1), dvec3(0, 0, 1), 0);
    EXPECT_NEAR(glm::dot(below.normal, -n), 1, 1e-6);
}

// Radiance's modifier rules: an instance or mesh with a modifier replaces every material inside (and rtrace
// -os names it); without one, the inside keeps its own, and surfaces or triangles without one are unseen.
TEST(Instance, ModifierOfAnInstanceOrMeshReplacesTheMaterialsInside) {
    ScopedRayPath path(kDir.c_str());
    TempFile voidObj("void.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    TestScene t(std::string(kFloor) +
                "void plastic red 0 0 5 .8 .1 .1 0 0\n"
                "void instance own 5 lamp.oct -t 0 0 0\n0\n0\n"
                "red instance painted 5 lamp.oct -t 5 0 0\n0\n0\n"
                "void mesh unseen 5 " +
                voidObj.path.string() +
                " -t 0 5 0\n0\n0\n"
                "red mesh seen 5 " +
                voidObj.path.string() + " -t 5 5 0\n0\n0\n");
    Integrator integrator(t.render, fixedSeed());
    auto names = [&](double x, double y) {
        RayRecord r = test::trace(integrator, dvec3(x + 0.2, y + 0.1, 3), dvec3(0, 0, -1), 0);
        const auto& o = t.scene.objects;
        return o[r.surfaceObject].name + " " + o[r.modifierObject].name;
    };
    EXPECT_EQ(names(0, 0), "panel bright");  // from above, the lamp's own panel (its back)
    EXPECT_EQ(names(5, 0), "painted red");
    EXPECT_EQ(names(0, 5), "floor grey");  // a void mesh of void triangles: unseen
    EXPECT_EQ(names(5, 5), "seen red");
}

// An octree that places itself is refused, not followed forever. (A normal octree: its header, the files it
// lists, no tree needed.)
TEST(Instance, OctreeHoldingItselfIsAnError) {
    std::string octree = "#?RADIANCE\nFORMAT=Radiance_octree\n\n";
    octree += std::string{char(0x01), char(0x1f)};  // 283 + 4
    for (const char* s : {"0", "0", "0", "1", "self.rad", ""}) octree += std::string(s) + '\0';
    octree += std::string{0, 0, 0, 1};
    auto dir = std::filesystem::temp_directory_path() / ("brume_self_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "self.oct", std::ios::binary) << octree;
    std::ofstream(dir / "self.rad") << "void instance me 1 self.oct\n0\n0\n";
    std::string error = "no error";
    {
        brume_test::ScopedDirectory here(dir);
        try {
            TestScene t("void instance outer 1 self.oct\n0\n0\n");
        } catch (const Error& e) {
            error = e.what();
        }
    }
    std::filesystem::remove_all(dir);
    EXPECT_EQ(error, "self.rad:1: instance \"me\" holds itself (self.oct)");
}
