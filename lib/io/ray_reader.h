// Rays on rtrace's standard input: "xorg yorg zorg xdir ydir zdir", as ASCII words (-fa), native floats
// (-ff) or native doubles (-fd).
#pragma once
#include <array>
#include <exception>
#include <istream>
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "util/error.h"

namespace brume {

class RayReader {
public:
    // `name` names the input in messages: "(stdin)" for the standard input.
    RayReader(std::istream& in, char format, std::string name)
        : in_(in), format_(format), name_(std::move(name)) {}
    // The next ray; false at the end of input. ASCII input is a ray a line (blank lines are skipped), binary
    // input a ray a record of six numbers. Anything that is not six finite numbers is an Error naming its
    // line or record: "(stdin):5: 4 numbers, a ray needs 6", "(stdin): ray 12: partial record, 20 of 24 bytes".
    bool next(std::array<double, 6>& ray);

    static constexpr size_t kLongestWord = 64;  // longer words are not numbers (Radiance reads 31 characters)

private:
    bool nextLine(std::array<double, 6>& ray);
    bool nextRecord(std::array<double, 6>& ray);
    int word(int c);
    double number() const;
    Error lineError(const std::string& what) const;
    Error recordError(const std::string& what) const;
    std::istream& in_;
    char format_;
    std::string name_;
    std::array<char, kLongestWord + 2> word_;  // the last ASCII word read, cut one past kLongestWord
    size_t wordLength_ = 0;
    long lines_ = 0;    // ASCII lines read to their end
    long records_ = 0;  // binary records read
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
// all (0: until the end of input). The work of a batch is done in one Sequence::run, so programs that
// batch alike (rtrace, mkcache) make the same irradiance cache records.
class RayBatches {
public:
    RayBatches(RayReader& reader, size_t size, long limit) : reader_(reader), size_(size), limit_(limit) {}
    // The next batch; false when there is none. Warns when the input ends before `limit` rays. A bad ray
    // ends the batch before it, which is returned whole; the reader's Error is thrown by the next call.
    bool next(std::vector<InputRay>& rays);
    // Rays read before the current batch: the index of its first ray, which seeds its samples.
    uint64_t first() const { return first_; }

private:
    bool read(std::array<double, 6>& ray);
    RayReader& reader_;
    size_t size_;
    long limit_, count_ = 0;
    uint64_t first_ = 0;
    bool done_ = false;
    std::exception_ptr error_;  // the reader's, once the rays before it are returned
};

}  // namespace brume
