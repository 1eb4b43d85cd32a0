// Radiance's transforms (the xf arguments of xform, instance, mesh and patterns): translations, rotations
// about the axes, uniform scaling and mirroring, applied in the order given; `-i n` repeats the group of
// transforms before the next `-i` n times.
#pragma once
#include <glm/mat4x4.hpp>

#include <span>
#include <string>
#include <string_view>

#include "geometry/ray.h"

namespace brume {

struct Transform {
    glm::dmat4 matrix{1.0};  // column vectors: p' = matrix · (p, 1)
    double scale = 1;        // the uniform scale; negative when mirrored an odd number of times

    // Summed in the order of Radiance's multp3/multv3, so that xform's output matches Radiance's digit for
    // digit (glm's matrix product rounds differently in the last bit).
    dvec3 point(const dvec3& p) const { return vector(p) + dvec3(matrix[3]); }
    // Directions and offsets; their length is multiplied by |scale|.
    dvec3 vector(const dvec3& v) const {
        const glm::dmat4& m = matrix;
        return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
                v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
    }
    bool mirrors() const { return scale < 0; }
    Transform inverse() const { return {glm::inverse(matrix), 1 / scale}; }
    // This transform followed by `next`.
    Transform then(const Transform& next) const { return {next.matrix * matrix, scale * next.scale}; }
};

// The frame of an instance or mesh (Radiance's object transform), in which patterns and the directions
// materials give work on its surfaces.
struct ObjectFrame {
    Transform toWorld;
    Transform toObject;  // its inverse
};

// Whether `arg` starts a transform: -t -s -i -rx -ry -rz -mx -my -mz.
bool isTransformOption(std::string_view arg);

struct ParsedTransform {
    Transform transform;
    size_t used = 0;  // arguments consumed: parsing stops at the first that is not part of a transform
};

// Reads transform arguments from the front of `args`, as Radiance does: an unknown option, a missing or
// non-numeric value, or a zero scale ends the transform there.
ParsedTransform parseTransform(std::span<const std::string> args);

}  // namespace brume
