// The exact shapes of surfaces, and what moving them and measuring them needs.
#pragma once
#include <optional>
#include <string>
#include <variant>

#include "geometry/shapes.h"
#include "geometry/transform.h"

namespace brume {

using Shape = std::variant<Sphere, Cone, Ring, Polygon>;

struct Surface {
    int object;  // the scene object it is (its index in Scene::objects)
    Shape shape;
    // Its own modifier is void: a surface of an instanced octree that only instances giving a modifier show.
    bool voidModifier = false;
};

// Whether the shape lies within ±1e18, the coordinates Embree can trace in single precision.
bool withinTraceableRange(const Shape& shape);

// The shape moved by `t` (uniform scale, rotation, mirroring); mirroring keeps its front where the mirrored
// normal points, as Radiance's xform and instances do.
Shape transformed(const Shape& shape, const Transform& t);

// The surface's area in scene units squared.
double area(const Shape& shape);

}  // namespace brume
