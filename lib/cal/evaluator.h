// Evaluating compiled .cal expressions, one Evaluator per thread over a shared Program.
#pragma once
#include <span>
#include <vector>

#include "cal/builtins.h"
#include "cal/channels.h"
#include "cal/program.h"
#include "cal/stack_depth.h"

namespace brume::cal {

// Usage per ray and pattern: begin(channels, args), then evaluate the pattern's expressions. Variables
// ('=' definitions) are computed at most once between two begin() calls, however many expressions use
// them; begin() again whenever the channels or the arguments change.
//
// Math errors follow Radiance: division by zero, an illegal power or a built-in's domain or range error
// give 0 and a warning (once per kind). A result that is still not finite (e.g. an overflowing sum)
// becomes 0 with a warning, so NaN never reaches the renderer. Errors of the .cal program itself
// (recursion too deep, a variable defined in terms of itself, a missing real argument) throw
// brume::Error.
class Evaluator {
public:
    explicit Evaluator(const Program& program);

    // `channels` and `args` must outlive the evaluations that follow.
    void begin(const Channels& channels, std::span<const double> args = {});

    double operator()(ExprId e);
    // A function of the program (e.g. a data pattern's function) applied to numeric arguments.
    double operator()(FuncId f, std::span<const double> values);

    // Arguments a function called through a FuncId, or a variadic built-in passed as a parameter, takes.
    static constexpr uint32_t kMaxArgs = 16;
    // Function calls one evaluation may make (a second or so) before it is an error rather than a hang;
    // folding a constant gives up much earlier and leaves the work to evaluation.
    static constexpr uint64_t kMaxCalls = 10'000'000;
    static constexpr uint64_t kMaxFoldCalls = 100'000;

private:
    friend class Compiler;
    struct Frame;
    // Thrown instead of a math warning while folding constants, which then leaves the node as it is.
    struct FoldFailure {};

    double evaluate(uint32_t entry, const Frame* frame);
    double eval(uint32_t node, const Frame* frame);
    double evalNode(const Node& n, const Frame* frame);
    double variable(const Node& n);
    double param(uint32_t index, const Frame* frame);
    double call(uint32_t function, const uint32_t* args, uint32_t count, const Frame* frame);
    double callBuiltin(uint32_t builtin, const uint32_t* args, uint32_t count, const Frame* frame);
    double callParam(const Node& n, const Frame* frame);
    double sum(const Node& n, const Frame* frame);
    double product(const Node& n, const Frame* frame);
    double power(const Node& n, const Frame* frame);
    double select(const Node& n, const Frame* frame);
    double extreme(const Node& n, const Frame* frame, bool wantMax);
    // For the Compiler: the value of a constant node; FoldFailure if it has a math error.
    double constantValue(uint32_t node);
    double mathError(const char* what);

    const Program& program_;
    RayInput ray_;
    uint64_t epoch_ = 1;
    std::vector<uint64_t> stamps_;  // epoch_ when the slot's value is current, ~epoch_ while computing it
    std::vector<double> values_;
    StackDepth stack_;
    uint64_t calls_ = 0;
    bool folding_ = false;
};

}  // namespace brume::cal
