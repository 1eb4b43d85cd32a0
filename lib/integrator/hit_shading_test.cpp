// What shades a hit and what a path is inside: the mists around a path's start, the volumes a ray enters and
// leaves as it crosses antimatter and mist boundaries unseen, and the hit as a material sees it.
#include "integrator/hit_shading.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/testing.h"

using namespace brume;
using namespace brume::integrator_testing;

namespace {

// Two nested mist spheres about the origin (r 1 and 3), a floor below, and an antimatter ball cutting it.
const std::string kVolumes = "void mist fog 0 0 3 .1 .1 .1\n"
                             "fog sphere blob 0 0 4 0 0 0 1\n"
                             "void mist haze 0 0 3 .05 .05 .05\n"
                             "haze sphere cloud 0 0 4 0 0 0 3\n"
                             "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                             "grey polygon floor 0 0 12 -5 -5 -4 5 -5 -4 5 5 -4 -5 5 -4\n"
                             "void antimatter hole 1 grey 0 0\n"
                             "hole sphere cut 0 0 4 0 0 -4 0.5\n";

SurfaceHit facingUp(const dvec3& perturbation = dvec3(0)) {
    SurfaceHit h{};
    h.t = 2;
    h.normal = dvec3(0, 0, 1);
    h.perturbation = perturbation;
    return h;
}

Shading shade(const dvec3& dir, const SurfaceHit& hit) {
    return shadingAt(Ray{dvec3(0, 0, 2), glm::normalize(dir)}, hit, true, nullptr);
}

}  // namespace

// A path starting inside both mists is in both, one between them only in the outer, one outside in none.
TEST(HitShading, APathStartsInTheMistsAroundItsOrigin) {
    Parts parts(kVolumes);
    int fog = parts.object("fog"), haze = parts.object("haze");
    PathState inBoth = parts.shading.startingAt(dvec3(0.1, 0.2, 0), parts.scratch);
    EXPECT_EQ(inBoth.mists.count, 2);
    EXPECT_TRUE(inBoth.mists.contains(fog));
    EXPECT_TRUE(inBoth.mists.contains(haze));
    PathState between = parts.shading.startingAt(dvec3(2, 0, 0), parts.scratch);
    EXPECT_EQ(between.mists.count, 1);
    EXPECT_TRUE(between.mists.contains(haze));
    EXPECT_EQ(parts.shading.startingAt(dvec3(4, 0, 1), parts.scratch).mists.count, 0);
}

// The thread's scratch remembers the last start (a picture's eye, asked for every pixel): the same point is
// answered from it, without probing the scene again (the memo's answer is emptied here to see it is the one
// returned).
TEST(HitShading, TheScratchRemembersTheLastStart) {
    Parts parts(kVolumes);
    const dvec3 eye(0.1, 0.2, 0);
    PathState first = parts.shading.startingAt(eye, parts.scratch);
    ASSERT_EQ(parts.scratch.lastStart, eye);
    EXPECT_EQ(parts.scratch.mistsAtLastStart.count, first.mists.count);
    parts.scratch.mistsAtLastStart = InsideVolumes{};
    EXPECT_EQ(parts.shading.startingAt(eye, parts.scratch).mists.count, 0);
    EXPECT_EQ(parts.shading.startingAt(eye + dvec3(1e-9, 0, 0), parts.scratch).mists.count, 2);
    Parts clear("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere ball 0 0 4 0 0 0 1\n");
    clear.shading.startingAt(eye, clear.scratch);
    EXPECT_FALSE(clear.scratch.lastStart);  // no mists: nothing to probe or remember
}

// Crossing an antimatter boundary inward enters its volume, which cuts the floor away; outward leaves it.
// Mist boundaries are entered and left alike. Materials are seen, unless cut away; no material lets rays on.
TEST(HitShading, UnseenBoundariesUpdateTheVolumesTheRayIsIn) {
    Parts parts(kVolumes);
    int hole = parts.object("hole"), fog = parts.object("fog"), grey = parts.object("grey");
    PathState state;
    EXPECT_TRUE(parts.shading.passes(-1, false, state));
    EXPECT_FALSE(parts.shading.passes(grey, false, state));
    EXPECT_TRUE(parts.shading.passes(hole, false, state));
    EXPECT_TRUE(state.clips.contains(hole));
    EXPECT_TRUE(parts.shading.passes(grey, false, state));  // cut away
    EXPECT_TRUE(parts.shading.passes(hole, true, state));
    EXPECT_EQ(state.clips.count, 0);
    EXPECT_FALSE(parts.shading.passes(grey, true, state));
    EXPECT_TRUE(parts.shading.passes(fog, false, state));
    EXPECT_TRUE(state.mists.contains(fog));
    EXPECT_TRUE(parts.shading.passes(fog, true, state));
    EXPECT_EQ(state.mists.count, 0);
}

// The material sees the normal turned toward the ray, and which side was hit.
TEST(HitShading, ShadingTurnsTheNormalTowardTheRay) {
    Shading front = shade(dvec3(0, 0, -1), facingUp());
    EXPECT_EQ(front.normal, dvec3(0, 0, 1));
    EXPECT_FALSE(front.backside);
    EXPECT_DOUBLE_EQ(front.cosine, 1);
    Shading back = shade(dvec3(0, 0.6, 0.8), facingUp());
    EXPECT_EQ(back.normal, dvec3(0, 0, -1));
    EXPECT_TRUE(back.backside);
    EXPECT_NEAR(back.cosine, 0.8, 1e-12);
    EXPECT_TRUE(back.flat);
}

// A perturbed normal (mesh normals, textures) turns with the surface; where it would face away from a grazing
// ray it is mirrored across the plane normal to the ray, so the material never sees light from behind.
TEST(HitShading, PerturbedNormalsStayFacingTheRay) {
    Shading tilted = shade(dvec3(0, 0, -1), facingUp(dvec3(0.5, 0, 0)));
    EXPECT_NEAR(glm::distance(tilted.normal, glm::normalize(dvec3(0.5, 0, 1))), 0, 1e-12);
    EXPECT_NEAR(tilted.cosine, 1 / std::sqrt(1.25), 1e-12);
    EXPECT_FALSE(tilted.flat);
    dvec3 grazing = glm::normalize(dvec3(1, 0, -0.1));
    Shading mirrored = shade(grazing, facingUp(dvec3(3, 0, 0)));
    EXPECT_NEAR(glm::length(mirrored.normal), 1, 1e-12);
    EXPECT_GT(glm::dot(mirrored.normal, -grazing), 0);
    EXPECT_NEAR(mirrored.cosine, glm::dot(mirrored.normal, -grazing), 1e-12);
}
