// The state a path carries from ray to ray — how the ray was chosen (which decides how it counts the light
// sources it meets), its bounces and weight, the closed volumes it is inside — and Russian roulette, which
// decides whether a path goes on.
#pragma once
#include <algorithm>
#include <numbers>

#include <glm/vec3.hpp>

#include "sampling/random.h"
#include "spectrum/spectrum.h"

namespace brume {

using glm::dvec3;

namespace integrator_detail {
constexpr double kPi = std::numbers::pi;
constexpr int kMaxCrossings = 64;     // surfaces a shadow ray may pass through
constexpr int kRouletteDepth = 64;    // past this many reflections roulette plays whatever -lr says
constexpr int kSafetyDepth = 200;     // roulette ends paths long before; this only bounds the stack
constexpr double kDistantSourceDistance = 1e10;  // T of rays meeting sources at infinity (Radiance's FHUGE)

// Veach's power heuristic (β = 2) for two strategies of densities a and b.
inline double powerHeuristic(double a, double b) { return a * a / (a * a + b * b); }
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

struct PathState {
    // Primary: the ray whose value is asked for; Specular: a child of a specular lobe; Sampled: a ray drawn
    // from a lobe (diffuse, glossy, a phase function), whose sources next-event estimation counted too.
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
    // A cosine-distributed ray from a point (`from`) that also aimed at the sky through portals: that
    // point's normal, for the share it keeps of the sky it meets (SkyPortals::rayShare); zero: all of it.
    // `aimedPerRay`: how many samples aimed there per ray (see aimedCount).
    dvec3 skyNormal{0};
    double aimedPerRay = 1;
    // Antimatter volumes the ray is inside, which hide the surfaces they cut; mists it is inside.
    InsideVolumes clips, mists;
    // Where contributions are collected (contributions.h): what a unit of radiance along the ray adds to the
    // query's value, kept by whoever spawned the ray; else null.
    const Spectrum* throughput = nullptr;
    // The query's own point is a sensor (rtrace -I, -i): its direct light is the answer itself, averaged with
    // nothing. Its children are not.
    bool sensor = false;
};

// Whether a path goes on past a scattering, and by how much its contribution grows if it does: Radiance's
// -lr and -lw, without bias (Russian roulette where Radiance stops a path).
class RussianRoulette {
public:
    RussianRoulette(int maxReflections, double minWeight) : maxReflections_(maxReflections), minWeight_(minWeight) {}

    // The child of `parent` past a scattering of coefficient `coef` (a reflection or not, for -lr); false
    // where the path ends. `boost` receives the inverse of the probability it went on. `byReflectance` plays
    // roulette by the coefficient (paths past -ab bounces) whatever a negative or zero -lr says; a positive
    // -lr is a hard limit still. `rays`: how many rays share the parent's estimate (the -ad paths of a first
    // bounce). Under roulette each weighs 1/rays of it, its contribution to the result, as Radiance's
    // path-traced ambient rays do: a path is played for by -lw when it no longer matters to the answer, not
    // after a fixed fall in light (2-3× less noise per CPU second in daylit rooms). The split alone never
    // takes a weight below -lw, since the roulette here plays once for all the rays; nor does it under a
    // hard -lw cut (a positive -lr), which would drop their light.
    bool spawn(const PathState& parent, PathState& child, const Spectrum& coef, bool reflection, Random& rng,
               float& boost, bool byReflectance = false, int rays = 1) const {
        double w = std::min(1.0, double(coef.maxValue()));
        child = parent;
        child.weight = parent.weight * w;
        if (maxReflections_ <= 0) child.weight = std::max(child.weight / rays, std::min(child.weight, minWeight_));
        child.reflections = parent.reflections + (reflection ? 1 : 0);
        child.depth = parent.depth + 1;
        child.viaMirror = -1;
        child.sensor = false;
        boost = 1.f;
        if (!(child.weight > 0) || child.depth > integrator_detail::kSafetyDepth) return false;
        if (maxReflections_ > 0) return child.weight >= minWeight_ && child.reflections <= maxReflections_;
        // Unbiased termination: below -lw by weight, past |lr| reflections by reflectance.
        double survive = 1;
        if (child.weight < minWeight_) survive = child.weight / minWeight_;
        // (Also past kRouletteDepth with -lr 0, so a closed box of perfect mirrors still ends its paths.)
        if (byReflectance || (maxReflections_ < 0 && child.reflections > -maxReflections_) ||
            child.reflections > integrator_detail::kRouletteDepth)
            survive *= std::min(0.95, w);
        if (survive < 1) {
            if (rng.uniform() >= survive) return false;
            boost = float(1 / survive);
            child.weight /= survive;
        }
        return true;
    }

private:
    int maxReflections_;  // -lr: > 0 a hard limit; ≤ 0 roulette past |lr| reflections
    double minWeight_;    // -lw
};

}  // namespace brume
