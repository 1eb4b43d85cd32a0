// What the .cal fuzz target does with one input, shared with the corpus replay test: parse it, compile
// every definition, evaluate a few. Errors (brume::Error) are fine; crashes and hangs are not, and a
// result that is not a finite number makes this return false.
#pragma once
#include <cmath>
#include <string_view>
#include <vector>

#include "cal/compiler.h"
#include "cal/evaluator.h"
#include "cal/parser.h"

namespace brume::cal {

inline bool exerciseCal(std::string_view text) {
    Library library;
    Compiler compiler(library);
    std::vector<ExprId> exprs;
    std::vector<FuncId> funcs;
    try {
        library.loadText(text, "fuzz.cal");
        // Each definition on its own, so that one bad definition does not hide the others.
        for (const Definition& d : parseDefinitions(text, "fuzz.cal")) {
            try {
                if (d.isFunction())
                    funcs.push_back(compiler.function(d.name, static_cast<int>(d.params.size()), {}, {}));
                else
                    exprs.push_back(compiler.expression(d.name, {}, {}));
            } catch (const Error&) {
            }
        }
    } catch (const Error&) {
        return true;
    }
    const Program program = std::move(compiler).finish();
    Evaluator evaluator(program);
    Channels channels;
    for (int c = 0; c < kChannelCount; ++c) channels[c] = .1 * c - 1;
    const std::vector<double> args{2, -1, .5}, values(Evaluator::kMaxArgs, .25);
    evaluator.begin(channels, args);
    // A few evaluations only: each may legitimately make up to Evaluator::kMaxCalls calls.
    constexpr size_t kEvaluations = 4;
    for (size_t i = 0; i < exprs.size() + funcs.size() && i < kEvaluations; ++i) {
        try {
            double v = i < exprs.size() ? evaluator(exprs[i]) : evaluator(funcs[i - exprs.size()], values);
            if (!std::isfinite(v)) return false;
        } catch (const Error&) {
        }
    }
    return true;
}

}  // namespace brume::cal
