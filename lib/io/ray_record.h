// What rtrace can report about a ray (its -o letters), and the rays of a primary ray's tree (-ot, -oT).
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "spectrum/spectrum.h"

namespace brume {

using glm::dvec3;

struct RayRecord {
    Spectrum value{0.f};
    double firstLength = std::numeric_limits<double>::infinity();      // L: to the first surface
    double effectiveLength = std::numeric_limits<double>::infinity();  // l: through specular pass-throughs
    dvec3 point{0};                                                     // p
    dvec3 normal{0};             // n: the normal turned toward the ray (textures will perturb it)
    dvec3 surfaceNormal{0};      // N: the surface's own normal, as the scene orients it
    glm::dvec2 uv{0};            // c: local (u, v) coordinates, Radiance's Lu Lv (meshes with uv)
    int surfaceObject = -1;   // s
    int modifierObject = -1;  // m
    Spectrum mirrored{0.f};   // r: the part of value that came by specular reflection
    double mirroredLength = std::numeric_limits<double>::infinity();  // x
};

// One ray of a primary ray's tree, for rtrace's trace output (-ot, -oT): depth 0 is the primary ray.
struct TracedRay {
    int depth;
    dvec3 org, dir;
    RayRecord record;
};

// Where the rays of a tree are collected, children before their parent, as Radiance prints them.
struct RayTree {
    std::vector<TracedRay> rays;
    bool withShadowRays = false;  // -oT
};

}  // namespace brume
