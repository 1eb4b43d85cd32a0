#include "scene/transform_object.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <sstream>

namespace brume {
namespace {

// The object of .rad text, transformed by xform's `words` with its options.
ObjectText transformed(const std::string& text, const std::vector<std::string>& words, ObjectTransform how = {}) {
    std::istringstream in(text);
    SceneTokenizer tokens(in.rdbuf(), "t.rad");
    ObjectText object = ObjectWords(tokens, "t.rad").read();
    ParsedTransform parsed = parseTransform(words);
    EXPECT_EQ(parsed.used, words.size());
    how.transform = parsed.transform;
    how.words = words;
    transformObject(object, how);
    return object;
}

std::string errorOf(const std::string& text) {
    try {
        transformed(text, {"-t", "1", "0", "0"});
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

dvec3 triple(const SceneObject& o, size_t i) { return {o.reals[i], o.reals[i + 1], o.reals[i + 2]}; }

// The normal of a polygon's first three vertices, by the right-hand rule as Radiance computes it.
dvec3 normalOf(const SceneObject& polygon) {
    dvec3 a = triple(polygon, 0), b = triple(polygon, 3), c = triple(polygon, 6);
    return glm::normalize(glm::cross(b - a, c - a));
}

void expectNear(const dvec3& a, const dvec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

const char* kFloor = "m polygon floor 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0";  // facing +z

TEST(TransformObject, RotatedPolygonNormalTurnsWithIt) {
    ObjectText o = transformed(kFloor, {"-rx", "90"});
    expectNear(normalOf(o.object), {0, -1, 0});
}

TEST(TransformObject, MirroredPolygonKeepsItsNormalFacingTheMirroredDirection) {
    // Mirroring across the floor's own plane turns the side it faces: the normal must follow.
    ObjectText down = transformed(kFloor, {"-mz"});
    expectNear(normalOf(down.object), {0, 0, -1});
    // Mirroring across a plane the normal lies in leaves it where it was.
    ObjectText across = transformed(kFloor, {"-mx"});
    expectNear(normalOf(across.object), {0, 0, 1});
    EXPECT_EQ(across.object.reals, (std::vector<double>{0, 1, 0, -1, 1, 0, -1, 0, 0, 0, 0, 0}));
}

TEST(TransformObject, InvertedPolygonFacesTheOtherWay) {
    ObjectTransform invert;
    invert.invert = true;
    expectNear(normalOf(transformed(kFloor, {}, invert).object), {0, 0, -1});
    // Inverted and mirrored: the two reversals cancel, the vertex order stays.
    expectNear(normalOf(transformed(kFloor, {"-mz"}, invert).object), {0, 0, 1});
}

TEST(TransformObject, TwoMirrorsAreARotationAndKeepTheVertexOrder) {
    ObjectText o = transformed(kFloor, {"-mx", "-my"});
    expectNear(normalOf(o.object), {0, 0, 1});
    expectNear(triple(o.object, 3), {-1, 0, 0});
}

TEST(TransformObject, SphereCentreMovesAndRadiusScalesByTheMagnitudeOfTheScale) {
    ObjectText o = transformed("m sphere s 0 0 4 1 2 3 0.5", {"-s", "-2", "-t", "1", "0", "0"});
    EXPECT_EQ(o.object.reals, (std::vector<double>{-1, -4, -6, 1}));
}

TEST(TransformObject, ConeEndsMoveAndBothRadiiScale) {
    ObjectText o = transformed("m cone c 0 0 8 0 0 0 0 0 1 .5 .25", {"-s", "2", "-t", "0", "0", "1"});
    EXPECT_EQ(o.object.reals, (std::vector<double>{0, 0, 1, 0, 0, 3, 1, .5}));
}

TEST(TransformObject, CylinderEndsMoveAndRadiusScales) {
    ObjectText o = transformed("m tube c 0 0 7 0 0 0 1 0 0 .5", {"-s", "3"});
    EXPECT_EQ(o.object.reals, (std::vector<double>{0, 0, 0, 3, 0, 0, 1.5}));
}

TEST(TransformObject, RingNormalTurnsAndFlipsWhenInverted) {
    const char* ring = "m ring r 0 0 8 1 0 0 0 0 1 0 .5";
    ObjectText turned = transformed(ring, {"-ry", "90"});
    expectNear(triple(turned.object, 0), {0, 0, -1});
    expectNear(triple(turned.object, 3), {1, 0, 0});
    ObjectTransform invert;
    invert.invert = true;
    expectNear(triple(transformed(ring, {}, invert).object, 3), {0, 0, -1});
}

TEST(TransformObject, DistantSourceDirectionTurnsAndItsAngleStays) {
    ObjectText o = transformed("m source sun 0 0 4 1 0 0 .5", {"-rz", "90", "-t", "5", "5", "5"});
    expectNear(triple(o.object, 0), {0, 1, 0});  // a direction: translation does not move it
    EXPECT_EQ(o.object.reals[3], .5);
}

TEST(TransformObject, SpotlightDirectionTurnsColourAndConeStay) {
    ObjectText o = transformed("void spotlight s 0 0 7 10 20 30 45 0 0 -1", {"-rx", "90"});
    EXPECT_EQ(std::vector<double>(o.object.reals.begin(), o.object.reals.begin() + 4),
              (std::vector<double>{10, 20, 30, 45}));
    expectNear(triple(o.object, 4), {0, 1, 0});
}

TEST(TransformObject, GlowRadiusOfInfluenceScales) {
    EXPECT_EQ(transformed("void glow g 0 0 4 1 1 1 2", {"-s", "-3"}).object.reals, (std::vector<double>{1, 1, 1, 6}));
}

TEST(TransformObject, MistKeepsItsOpticalDepthWhenScaled) {
    // Twice the size, half the extinction per unit length: the same light gets through.
    ObjectTransform named;
    named.prefix = "p";
    ObjectText o = transformed("void mist fog 2 lamp a>b 0 7 .2 .4 .8 .9 .9 .9 .5", {"-s", "2"}, named);
    EXPECT_EQ(o.object.reals, (std::vector<double>{.1, .2, .4, .9, .9, .9, .5}));
    // Its sources are surfaces, renamed like them.
    EXPECT_EQ(o.object.strings, (std::vector<std::string>{"p.lamp", "p.a>p.b"}));
    EXPECT_EQ(o.object.name, "fog");
}

TEST(TransformObject, DielectricAndInterfaceTransmittanceKeepOpticalDepthWhenScaled) {
    ObjectText d = transformed("void dielectric w 0 0 5 .81 .64 1 1.33 0", {"-s", "2"});
    EXPECT_NEAR(d.object.reals[0], .9, 1e-15);
    EXPECT_NEAR(d.object.reals[1], .8, 1e-15);
    EXPECT_EQ(std::vector<double>(d.object.reals.begin() + 2, d.object.reals.end()), (std::vector<double>{1, 1.33, 0}));
    ObjectText i = transformed("void interface w 0 0 8 .81 .81 .81 1.33 .64 .64 .64 1.5", {"-s", "2"});
    EXPECT_NEAR(i.object.reals[2], .9, 1e-15);
    EXPECT_NEAR(i.object.reals[6], .8, 1e-15);
    EXPECT_EQ(i.object.reals[7], 1.5);
}

TEST(TransformObject, TextAnchorMovesAndItsAxesTurn) {
    ObjectText o = transformed("void brighttext t 2 helvet.fnt Hi 0 10 1 0 0 1 0 0 0 0 -1 .1",
                               {"-rz", "90", "-t", "0", "0", "1"});
    expectNear(triple(o.object, 0), {0, 1, 1});
    expectNear(triple(o.object, 3), {0, 1, 0});
    expectNear(triple(o.object, 6), {0, 0, -1});
    EXPECT_EQ(o.object.reals[9], .1);
}

TEST(TransformObject, FunctionTypesCarryTheTransformToTheirFunctions) {
    // "-i 1" first closes any -i of the object's own transform, which would otherwise repeat the new one.
    EXPECT_EQ(transformed("void brightfunc f 2 v f.cal 0 0", {"-rz", "90"}).object.strings,
              (std::vector<std::string>{"v", "f.cal", "-i", "1", "-rz", "90"}));
    EXPECT_EQ(transformed("void colorpict p 4 r g b x.hdr 0 0", {"-i", "2", "-s", "3"}).object.strings,
              (std::vector<std::string>{"r", "g", "b", "x.hdr", "-i", "2", "-s", "3"}));
    EXPECT_EQ(transformed("void texfunc f 2 v f.cal 0 0", {}).object.strings, (std::vector<std::string>{"v", "f.cal"}));
}

TEST(TransformObject, InstancesAndMeshesCarryTheTransform) {
    EXPECT_EQ(transformed("m instance chair 3 c.oct -s 2 0 0", {"-t", "1", "0", "0"}).object.strings,
              (std::vector<std::string>{"c.oct", "-s", "2", "-i", "1", "-t", "1", "0", "0"}));
    EXPECT_EQ(transformed("m mesh pot 1 p.rtm 0 0", {"-mx"}).object.strings,
              (std::vector<std::string>{"p.rtm", "-i", "1", "-mx"}));
}

TEST(TransformObject, MaterialsWithoutGeometryAreUnchanged) {
    for (const char* text : {"void plastic p 0 0 5 .5 .5 .5 0 0", "void light l 0 0 3 1 2 3",
                             "void mirror m 1 x 0 3 .9 .9 .9", "void antimatter a 1 p 0 0"}) {
        ObjectText o = transformed(text, {"-s", "3", "-rx", "10"});
        std::istringstream in(text);
        SceneTokenizer tokens(in.rdbuf(), "t.rad");
        ObjectText original = ObjectWords(tokens, "t.rad").read();
        EXPECT_EQ(o.object.reals, original.object.reals) << text;
        EXPECT_EQ(o.object.strings, original.object.strings) << text;
    }
}

TEST(TransformObject, InvertedSurfacesChangeTypeInsideOut) {
    ObjectTransform invert;
    invert.invert = true;
    EXPECT_EQ(transformed("m sphere s 0 0 4 0 0 0 1", {}, invert).object.type, "bubble");
    EXPECT_EQ(transformed("m cup c 0 0 8 0 0 0 0 0 1 1 1", {}, invert).object.type, "cone");
    EXPECT_EQ(transformed("m cylinder c 0 0 7 0 0 0 0 0 1 1", {}, invert).object.type, "tube");
    EXPECT_EQ(transformed("void plastic p 0 0 5 0 0 0 0 0", {}, invert).object.type, "plastic");
}

TEST(TransformObject, SurfacesAreRenamedAndRemodifiedModifiersKeepTheirNames) {
    ObjectTransform how;
    how.prefix = "copy";
    how.modifier = "steel";
    ObjectText surface = transformed("red sphere s 0 0 4 0 0 0 1", {}, how);
    EXPECT_EQ(surface.object.name, "copy.s");
    EXPECT_EQ(surface.modifier, "steel");
    ObjectText instance = transformed("void instance i 1 x.oct 0 0", {}, how);
    EXPECT_EQ(instance.object.name, "copy.i");
    ObjectText material = transformed("pat plastic red 0 0 5 1 0 0 0 0", {}, how);
    EXPECT_EQ(material.object.name, "red");
    EXPECT_EQ(material.modifier, "pat");
}

TEST(TransformObject, UnknownTypesAndMisfitArgumentsAreErrorsAtTheirLine) {
    EXPECT_EQ(errorOf("m blob b 0 0 0"), "t.rad:1: unknown object type 'blob'");
    EXPECT_EQ(errorOf("m polygon p 0 0 4 0 0 0 1"), "t.rad:1: bad polygon 'p': expected no strings and reals in threes");
    EXPECT_EQ(errorOf("\nm sphere s 1 x 0 4 0 0 0 1"), "t.rad:2: bad sphere 's': expected no strings and 4 reals");
    EXPECT_EQ(errorOf("void mist f 0 0 2 .1 .1"), "t.rad:1: bad mist 'f': expected 0 or 3 to 7 reals");
    EXPECT_EQ(errorOf("void colortext t 1 x 0 3 0 0 0"), "t.rad:1: bad colortext 't': expected at least 9 reals");
    EXPECT_EQ(errorOf("void smoke s 0 0 3 1 1 1"),
              "t.rad:1: bad smoke 's': expected files, no integers and 3, 6 or 7 reals");
}

TEST(TransformObject, SmokeIsRenamedButNotMovedItsGridsPlaceIt) {
    ObjectTransform how;
    how.prefix = "copy";
    how.modifier = "soot";
    ObjectText smoke = transformed("void smoke s 1 room.vdb 0 3 8700 8700 8700", {"-t", "0", "0", "0"}, how);
    EXPECT_EQ(smoke.object.name, "copy.s");
    EXPECT_EQ(smoke.modifier, "soot");
    EXPECT_EQ(smoke.object.strings, std::vector<std::string>{"room.vdb"});
    EXPECT_EQ(errorOf("void smoke s 1 room.vdb 0 3 1 1 1"), "t.rad:1: cannot transform smoke 's' yet");
}

}  // namespace
}  // namespace brume
