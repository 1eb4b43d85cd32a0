// One record's contributions (rcontrib): the sink its rays' paths tell, summing per modifier and bin the
// coefficients (or, with -V, coefficient × radiance), each bin as Radiance's rcontrib finds it: the bin
// expression at the ray toward the source, rounded to the nearest whole number; below −0.5 ignored; past the
// last bin ignored with a warning.
#pragma once
#include <optional>
#include <vector>

#include "cal/evaluator.h"
#include "contrib/modifier_bins.h"
#include "integrator/contributions.h"

namespace brume {

class ContributionTally final : public ContributionSink {
public:
    // `values`: contributions (-V) rather than coefficients; `channels`: the colour's (3, or spectral bands).
    ContributionTally(const ModifierBins& bins, bool values, int channels);

    void add(const Contribution& c) override;
    // Back to zero, for the next record.
    void clear();
    // columns() × channels sums, bin by bin.
    const std::vector<double>& sums() const { return sums_; }
    // Contributions ignored for a bin past the last (the warning names the first).
    long outOfRange() const { return outOfRange_; }
    int firstOutOfRange() const { return firstOutOfRange_; }

private:
    double binValue(int m, const Contribution& c);

    const ModifierBins& bins_;
    bool values_;
    int channels_;
    std::vector<std::optional<cal::Evaluator>> evaluators_;  // one per modifier whose bin is not a constant
    std::vector<double> sums_;
    long outOfRange_ = 0;
    int firstOutOfRange_ = -1;
};

}  // namespace brume
