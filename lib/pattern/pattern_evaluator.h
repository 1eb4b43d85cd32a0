// Per-thread state for evaluating patterns: the ray values of the pattern being evaluated and the .cal
// evaluator, whose variables are computed once per pattern and hit.
#pragma once
#include "cal/evaluator.h"
#include "pattern/modifier_chain.h"

namespace brume {

class PatternEvaluator {
public:
    explicit PatternEvaluator(const ModifierChain& chain) : eval(chain.library().program()) {}

    cal::Channels channels{};
    cal::Evaluator eval;
};

}  // namespace brume
