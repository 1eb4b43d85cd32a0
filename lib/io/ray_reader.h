// Rays on rtrace's standard input: "xorg yorg zorg xdir ydir zdir", as ASCII words (-fa), native floats
// (-ff) or native doubles (-fd).
#pragma once
#include <array>
#include <istream>
#include <vector>

#include "geometry/ray.h"

namespace brume {

class RayReader {
public:
    RayReader(std::istream& in, char format) : in_(in), format_(format) {}
    // The next ray; false at the end of input. As in Radiance, ASCII input ends at the first word that
    // is not a number; a partial ray at the end is reported through partial().
    bool next(std::array<double, 6>& ray);
    bool partial() const { return partial_; }

private:
    bool word(double& v);
    std::istream& in_;
    char format_;
    bool partial_ = false;
};

// A ray as rtrace takes it: its direction made unit, the given length kept (-ld); a zero direction asks
// for a flush.
struct InputRay {
    dvec3 org, dir;
    double maxDistance;
    bool zero;
};

// `r` as rtrace traces it: a direction of any finite length, however small or large, is made unit; only
// 0 0 0 is zero.
InputRay inputRay(const std::array<double, 6>& r);

constexpr size_t kRayBatchSize = 4096;  // rtrace's rays per batch when -x does not set it

// rtrace's batches of rays: up to `size` rays, ending early after a flush request; at most `limit` rays in
// all (0: until the end of input). The work of a batch is done in one Integrator::forEach, so programs that
// batch alike (rtrace, mkcache) make the same irradiance cache records.
class RayBatches {
public:
    RayBatches(RayReader& reader, size_t size, long limit) : reader_(reader), size_(size), limit_(limit) {}
    // The next batch; false when there is none. Warns when the input ends before `limit` rays.
    bool next(std::vector<InputRay>& rays);
    // Rays read before the current batch: the index of its first ray, which seeds its samples.
    uint64_t first() const { return first_; }

private:
    RayReader& reader_;
    size_t size_;
    long limit_, count_ = 0;
    uint64_t first_ = 0;
    bool done_ = false;
};

}  // namespace brume
