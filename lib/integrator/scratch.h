// One thread's working memory for the rays it traces, handed to each work item by the loop that runs them:
// the state of pattern evaluation, where the last path started (and the mists around it), and arrays reused
// from ray to ray so that shading allocates nothing.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "integrator/path_state.h"
#include "pattern/pattern_evaluator.h"
#include "sampling/spherical_polygon.h"
#include "world/render_scene.h"

namespace brume {

// A portal as one point sees it: its share of the samples aimed at the sky, and its solid angle.
struct PortalChoice {
    double probability = 0;
    SphericalPolygon view;
};

// A source to draw distances toward in media (a lamp, or the flames' bounding sphere): its guessed single
// scattering along the ray, where it is, its radius and intensity.
struct SourceGuess {
    double guess;
    dvec3 centre;
    double radius, intensity;
};

struct Scratch {
    explicit Scratch(const RenderScene& scene) : patterns(scene.modifiers()) {}

    PatternEvaluator patterns;
    // The last point a path started from and the mists it lies in (a picture's eye is asked for every pixel).
    std::optional<dvec3> lastStart;
    InsideVolumes mistsAtLastStart;
    std::vector<double> perSource;                               // next-event estimation's value per source
    std::vector<SourceGuess> sourceGuesses;                      // sources to draw distances toward in media
    std::vector<PortalChoice> portals;                           // how a point sees each portal
};

}  // namespace brume
