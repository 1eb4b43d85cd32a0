#include "contrib/contribution_tally.h"

#include <cmath>

namespace brume {

ContributionTally::ContributionTally(const ModifierBins& bins, bool values, int channels)
    : bins_(bins), values_(values), channels_(channels), sums_(size_t(bins.columns()) * channels, 0.0) {
    evaluators_.reserve(bins.modifiers().size());
    for (const ModifierBins::Tallied& m : bins.modifiers())
        evaluators_.emplace_back(m.constant ? std::nullopt : std::optional<cal::Evaluator>(std::in_place, m.program));
}

void ContributionTally::clear() { std::fill(sums_.begin(), sums_.end(), 0.0); }

// The bin expression's value for a contribution: Brume's reinhartb.cal natively, else the .cal.
double ContributionTally::binValue(int m, const Contribution& c) {
    const ModifierBins::Tallied& modifier = bins_.modifiers()[m];
    if (modifier.reinhart) return modifier.reinhart->bin(c.dir);
    cal::Channels channels{};
    channels[cal::Dx] = c.dir.x, channels[cal::Dy] = c.dir.y, channels[cal::Dz] = c.dir.z;
    channels[cal::Nx] = c.normal.x, channels[cal::Ny] = c.normal.y, channels[cal::Nz] = c.normal.z;
    channels[cal::Px] = c.point.x, channels[cal::Py] = c.point.y, channels[cal::Pz] = c.point.z;
    channels[cal::T] = std::isfinite(c.distance) ? c.distance : integrator_detail::kDistantSourceDistance;
    channels[cal::Rdot] = -glm::dot(c.dir, c.normal);
    cal::Evaluator& evaluator = *evaluators_[m];
    evaluator.begin(channels);
    return evaluator(modifier.bin);
}

void ContributionTally::add(const Contribution& c) {
    int m = bins_.indexOf(c.modifier);
    if (m < 0) return;
    const ModifierBins::Tallied& modifier = bins_.modifiers()[m];
    int bin = 0;
    if (!modifier.constant) {
        double value = binValue(m, c);
        if (!(value > -0.5)) return;  // Radiance's rcontrib ignores negative bins silently
        if (value + 0.5 >= modifier.bins) {
            if (outOfRange_++ == 0) firstOutOfRange_ = std::isfinite(value) ? int(std::min(value + 0.5, 2e9)) : -1;
            return;
        }
        bin = int(value + 0.5);
    }
    double* sum = &sums_[size_t(modifier.column + bin) * channels_];
    for (int k = 0; k < channels_; ++k)
        sum[k] += values_ ? double(c.coefficient[k]) * c.radiance[k] : double(c.coefficient[k]);
}

}  // namespace brume
