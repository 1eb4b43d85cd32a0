// rtrace's outputs of a ray, filled beside the transport: what the ray met, its effective length through the
// specular children that brought most of its value, and with -ot/-oT its tree of rays.
#include "integrator/ray_outputs.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace brume;

namespace {

SurfaceHit hitAt(double t) {
    SurfaceHit h{};
    h.t = t;
    h.point = dvec3(1, 2, t);
    h.normal = dvec3(0, 0, -1);
    h.uv = glm::dvec2(0.25, 0.75);
    return h;
}

RayRecord withLength(double length) {
    RayRecord r;
    r.firstLength = r.effectiveLength = length;
    return r;
}

}  // namespace

// A scope sends the rays traced in it to its record, then gives the ray before its own back.
TEST(RayOutputs, ScopeRestoresTheRecordBefore) {
    RayOutputs outputs;
    RayRecord a, b;
    EXPECT_EQ(outputs.record(), nullptr);
    {
        RayOutputs::Scope first(outputs, &a);
        EXPECT_EQ(outputs.record(), &a);
        {
            RayOutputs::Scope none(outputs, nullptr);
            EXPECT_EQ(outputs.record(), nullptr);
            RayOutputs::Scope second(outputs, &b);
            EXPECT_EQ(outputs.record(), &b);
        }
        EXPECT_EQ(outputs.record(), &a);
    }
    EXPECT_EQ(outputs.record(), nullptr);
}

// A hit fills the lengths (effective = first, until specular children say otherwise), the point, the normal
// as shaded and the surface's own, (u, v), the object and its material.
TEST(RayOutputs, AHitFillsWhatTheRayMet) {
    RayOutputs outputs;
    RayRecord record;
    RayOutputs::Scope scope(outputs, &record);
    outputs.hit(hitAt(3), dvec3(0, 0, 1), 5, 2);
    EXPECT_EQ(record.firstLength, 3);
    EXPECT_EQ(record.effectiveLength, 3);
    EXPECT_EQ(record.point, dvec3(1, 2, 3));
    EXPECT_EQ(record.normal, dvec3(0, 0, 1));
    EXPECT_EQ(record.surfaceNormal, dvec3(0, 0, -1));
    EXPECT_EQ(record.uv, glm::dvec2(0.25, 0.75));
    EXPECT_EQ(record.surfaceObject, 5);
    EXPECT_EQ(record.modifierObject, 2);
    outputs.distantSource(7, 6, dvec3(0, 1, 0));
    EXPECT_EQ(record.surfaceObject, 7);
    EXPECT_EQ(record.modifierObject, 6);
    EXPECT_EQ(record.normal, dvec3(0, -1, 0));  // a source at infinity faces the ray
}

// The effective length goes through the brightest specular child; the mirrored part and its length come from
// reflections only. Where no child brings half the ray's value, the first surface's length is kept.
TEST(RayOutputs, TheBrightestSpecularChildDecidesTheEffectiveLength) {
    RayOutputs outputs;
    RayRecord record;
    RayOutputs::Scope scope(outputs, &record);
    outputs.hit(hitAt(2), dvec3(0, 0, 1), 1, 1);
    double strongest = 0;
    outputs.specularPart(Spectrum(0.3f), true, withLength(5), strongest);
    EXPECT_EQ(record.effectiveLength, 7);
    EXPECT_EQ(record.mirroredLength, 7);
    outputs.specularPart(Spectrum(0.6f), false, withLength(1), strongest);
    EXPECT_EQ(record.effectiveLength, 3);
    EXPECT_EQ(record.mirroredLength, 7);
    EXPECT_FLOAT_EQ(record.mirrored[0], 0.3f);
    EXPECT_FLOAT_EQ(strongest, 0.6);
    outputs.shaded(Spectrum(1.0f), strongest);  // .6 of 1: the transmitted child's length stays
    EXPECT_EQ(record.effectiveLength, 3);
    outputs.shaded(Spectrum(1.5f), strongest);  // .6 of 1.5: less than half, the surface's own
    EXPECT_EQ(record.effectiveLength, 2);
}

// A surface passed through unseen (antimatter, a mist's boundary) leaves the ray the record of what lies
// beyond, its lengths counted from this ray's origin: the surface's distance added.
TEST(RayOutputs, PassingThroughAddsTheSurfacesDistance) {
    RayOutputs outputs;
    RayRecord record, beyond = withLength(2);
    beyond.effectiveLength = 4;
    beyond.surfaceObject = 9;
    RayOutputs::Scope scope(outputs, &record);
    outputs.passedThrough(beyond, 1.5);
    EXPECT_EQ(record.firstLength, 3.5);
    EXPECT_EQ(record.effectiveLength, 5.5);
    EXPECT_EQ(record.surfaceObject, 9);
}

// In a tree, children come before their parent, one level deeper; the primary ray takes the record asked of
// it, the others records of their own. Shadow rays only with -oT, as children of the ray that cast them.
TEST(RayOutputs, TreeRaysComeAfterTheirChildren) {
    for (bool withShadows : {false, true}) {
        RayTree tree;
        tree.withShadowRays = withShadows;
        RayOutputs outputs(&tree);
        EXPECT_EQ(outputs.wantsShadowRays(), withShadows);
        RayRecord primary;
        {
            RayOutputs::Scope asked(outputs, &primary);
            RayOutputs::TreeRay root(outputs, dvec3(0), dvec3(0, 0, 1));
            outputs.hit(hitAt(2), dvec3(0, 0, 1), 1, 1);
            if (outputs.wantsShadowRays())
                outputs.shadowRay(dvec3(1, 2, 2), LightSample{dvec3(1, 0, 0), 4, 1, dvec3(-1, 0, 0)}, 3, 4, Spectrum(5.f));
            {
                RayOutputs::Scope notAsked(outputs, nullptr);
                RayOutputs::TreeRay child(outputs, dvec3(1, 2, 2), dvec3(0, 1, 0));
                outputs.hit(hitAt(6), dvec3(0, 0, 1), 8, 8);
                child.end(Spectrum(0.5f));
            }
            root.end(Spectrum(2.f));
        }
        size_t shadows = withShadows ? 1 : 0;
        ASSERT_EQ(tree.rays.size(), 2 + shadows);
        if (withShadows) {
            const TracedRay& shadow = tree.rays[0];
            EXPECT_EQ(shadow.depth, 1);
            EXPECT_EQ(shadow.record.point, dvec3(5, 2, 2));
            EXPECT_EQ(shadow.record.firstLength, 4);
            EXPECT_EQ(shadow.record.surfaceObject, 3);
            EXPECT_FLOAT_EQ(shadow.record.value[0], 5.f);
        }
        const TracedRay &child = tree.rays[shadows], &root = tree.rays[shadows + 1];
        EXPECT_EQ(child.depth, 1);
        EXPECT_EQ(child.record.surfaceObject, 8);
        EXPECT_FLOAT_EQ(child.record.value[0], 0.5f);
        EXPECT_EQ(root.depth, 0);
        EXPECT_EQ(root.dir, dvec3(0, 0, 1));
        EXPECT_FLOAT_EQ(primary.value[0], 2.f);
        EXPECT_EQ(primary.surfaceObject, 1);
    }
    RayOutputs none;
    EXPECT_FALSE(none.wantsShadowRays());
}

// A sensor stands for a primary ray: the rays traced for it are its children, and it closes the tree at depth 0.
TEST(RayOutputs, ASensorIsTheRootOfItsTree) {
    RayTree tree;
    RayOutputs outputs(&tree);
    outputs.beginSensor();
    {
        RayOutputs::Scope notAsked(outputs, nullptr);
        RayOutputs::TreeRay ray(outputs, dvec3(0), dvec3(0, 0, 1));
        ray.end(Spectrum(1.f));
    }
    RayRecord sensor;
    outputs.endSensor(dvec3(0), dvec3(0, 0, -1), sensor, Spectrum(3.f));
    ASSERT_EQ(tree.rays.size(), 2u);
    EXPECT_EQ(tree.rays[0].depth, 1);
    EXPECT_EQ(tree.rays[1].depth, 0);
    EXPECT_FLOAT_EQ(tree.rays[1].record.value[0], 3.f);
}
