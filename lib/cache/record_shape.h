// How the cache shapes its records' zones: Brume's adaptive records, or the classic Ward–Heckbert records
// kept as a baseline for benchmarks. Everything else (sampling, gradients, lookup, files) is shared.
#pragma once

namespace brume {

struct RecordShape {
    enum class Kind { Adaptive, Classic } kind = Kind::Adaptive;
    double accuracy = 0.1;  // -aa: the relative error a record may make over its zone
    // Radiance's bounds on a record's radius before its -aa scaling: the scene's size / -ar, and 64 times
    // that (at most a fifth of the scene).
    double minRadius = 0.01, maxRadius = 1;
    // The largest angle between a record's normal and a lookup's (Radiance: 10° + -aa radians).
    double maxAngle() const;
};

}  // namespace brume
