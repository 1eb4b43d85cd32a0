// Per-thread state for evaluating patterns: function-file variables computed once per hit.
#pragma once

#include "pattern/modifier_chain.h"

namespace brume {

class PatternEvaluator {
public:
    explicit PatternEvaluator(const ModifierChain& chain) {}
};

}  // namespace brume
