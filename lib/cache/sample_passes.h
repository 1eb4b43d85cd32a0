// How many passes over its strata a record's rays make: decided once, after the first pass, from that pass's
// standard error (RaySamples::meanStandardError), so that the mean of all passes reaches a target relative
// error. Deciding once keeps the record nearly unbiased: a rule that stopped as soon as the samples looked
// good would stop more often on samples that missed a rare bright path, and keep their low mean.
#pragma once
#include <algorithm>
#include <cmath>

namespace brume {

constexpr int kMaxSamplePasses = 8;  // at most 8× -ad rays for one record

// The passes (1 to `most`) that bring a first pass's `relativeError` under `target`: the error falls as
// 1/√passes.
inline int samplePasses(double relativeError, double target, int most = kMaxSamplePasses) {
    if (!(relativeError > target) || !(target > 0)) return 1;
    double ratio = relativeError / target;
    return int(std::min(std::ceil(ratio * ratio), double(std::max(1, most))));
}

}  // namespace brume
