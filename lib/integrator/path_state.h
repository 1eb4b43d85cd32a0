// The state a path carries from ray to ray, and the per-ray context, shared by the integrator's parts.
#pragma once
#include <algorithm>
#include <numbers>

#include "integrator/integrator.h"

namespace brume {

namespace integrator_detail {
constexpr double kPi = std::numbers::pi;
constexpr int kMaxCrossings = 64;     // surfaces a shadow ray may pass through
constexpr int kRouletteDepth = 64;    // past this many reflections roulette plays whatever -lr says
constexpr int kSafetyDepth = 200;     // roulette ends paths long before; this only bounds the stack
constexpr double kDistantSourceDistance = 1e10;  // T of rays meeting sources at infinity (Radiance's FHUGE)

inline double powerHeuristic(double a, double b) { return a * a / (a * a + b * b); }

// The hit as a material sees it: the normal, perturbed (by mesh normals and a texture's `texture`), turned
// toward the ray, and which side was hit.
inline Shading shadingAt(const Ray& ray, const SurfaceHit& hit, bool flat, const ObjectFrame* object,
                         const dvec3& texture = dvec3(0)) {
    double along = glm::dot(hit.normal, ray.dir);
    bool backside = along > 0;
    Shading sh{hit.point, backside ? -hit.normal : hit.normal, ray.dir, std::abs(along), backside, flat, hit.t};
    sh.object = object;
    dvec3 perturbation = hit.perturbation + texture;
    if (perturbation == dvec3(0)) return sh;
    // Radiance's raynormal: the perturbed normal turns with the surface; where it would face away from the
    // ray, it is mirrored across the plane normal to the ray; its cosine is kept at least 0.001.
    dvec3 n = hit.normal + perturbation;
    double len = glm::length(n);
    if (!(len > 0) || !std::isfinite(len)) return sh;  // Radiance: "illegal normal perturbation", unperturbed
    n = (backside ? -n : n) / len;
    double cosine = -glm::dot(n, ray.dir);
    if (cosine <= 0) {
        n += 2 * cosine * ray.dir;
        cosine = -cosine;
    }
    sh.normal = n;
    sh.cosine = std::max(cosine, 0.001);
    sh.flat = false;
    return sh;
}

// The patterns' colour, and the texture's perturbation added to the hit's own (mesh normals), as Radiance's
// raytexture adds to the ray's before raynormal.
inline void applyTexturing(Shading& sh, const Texturing& t, const Ray& ray, const SurfaceHit& hit) {
    if (glm::dot(t.perturbation, t.perturbation) > 1e-12) sh = shadingAt(ray, hit, false, sh.object, t.perturbation);
    sh.pattern = t.color;
}
}  // namespace integrator_detail

// Closed volumes (scene objects) a ray is inside, in the order it entered them: known from the boundaries it
// crossed, as in Radiance.
struct InsideVolumes {
    static constexpr int kMax = 8;
    int objects[kMax];
    int count = 0;

    bool contains(int object) const { return std::find(objects, objects + count, object) != objects + count; }
    void enter(int object) {
        if (count < kMax && !contains(object)) objects[count++] = object;
    }
    void leave(int object) {
        int* end = std::remove(objects, objects + count, object);
        count = int(end - objects);
    }
};

// How the ray being traced was chosen, which decides how it counts the light sources it meets.
struct Integrator::PathState {
    enum class Kind { Primary, Specular, Sampled } kind = Kind::Primary;
    int reflections = 0;   // for -lr
    int ambientLevel = 0;  // diffuse bounces so far, for -ab and -ad
    double weight = 1;     // Radiance's ray weight, for -lw
    // For sampled rays: where they left, with which density × count (for MIS) and that point's weight.
    dvec3 from{0};
    double sampledDensity = 0;
    double fromWeight = 1;
    double fromSubdivision = 0;  // the -ds ratio next-event estimation used there
    int depth = 0;
    // A sampled ray just reflected by this planar mirror: sources it meets now were reached by
    // next-event estimation through their mirror images.
    int viaMirror = -1;
    // Antimatter volumes the ray is inside, which hide the surfaces they cut; mists it is inside.
    InsideVolumes clips, mists;
};

// What a work item or a record's computation learns from the irradiance cache: where records were missing.
struct Integrator::CacheVisit {
    bool waits = false;   // a work item waits for the records it misses (and runs again); records' rays do not
    bool missed = false;  // it missed one
    uint64_t key = 0;     // seeds the requests: key and count
    uint64_t count = 0;
    std::vector<RecordRequest> requests;
};

struct Integrator::Context {
    Random rng;
    RayTree* tree = nullptr;
    int depth = 0;  // of the ray being traced in its tree
    CacheVisit* visit = nullptr;
};


}  // namespace brume
