// What a cache lookup, a record request or a light sample is about: a point where light arrives, the normal
// of the surface there (none in a medium, where light arrives from every direction), the diffuse bounce of
// the path that reached it, and the scene's instant.
#pragma once
#include <optional>

#include <glm/vec3.hpp>

namespace brume {

struct Receiver {
    glm::dvec3 point{0};
    std::optional<glm::dvec3> normal;  // unit; on a surface the side light arrives on
    int level = 0;                     // diffuse bounces before this point (0: seen from a primary ray)
    double time = 0;                   // the scene's instant, s (-T)
};

}  // namespace brume
