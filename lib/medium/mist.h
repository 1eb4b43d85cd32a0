// Radiance's `mist`: not a surface but the boundary of a volume of medium. A ray crossing it inward (its
// surfaces face outward) travels on in a medium with the mist's extinction added, and its albedo and g in
// place of the medium's if it gives them; crossing it outward takes them back.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "medium/homogeneous_medium.h"
#include "scene/scene.h"

namespace brume {

struct Mist {
    Spectrum extinction{0.f};
    std::optional<Spectrum> albedo;
    std::optional<double> g;
    // Radiance's list of the sources whose light the mist scatters. Brume scatters every source's light in
    // every medium; the names are only checked.
    std::vector<std::string> sources;

    // The medium inside this mist, for a ray that was in `outside`.
    HomogeneousMedium inside(HomogeneousMedium outside) const {
        outside.extinction += extinction;
        if (albedo) outside.albedo = *albedo;
        if (g) outside.g = *g;
        return outside;
    }
};

// `mod mist id  N source…  0  0…7 [rext gext bext [ralb galb balb [g]]]` (Radiance takes the extinction from 3
// reals on, the albedo from 6, g from 7). Throws Error at the object's line for other counts and for
// negative extinction, albedo outside [0, 1] or |g| ≥ 1.
Mist readMist(const SceneObject& object);

}  // namespace brume
