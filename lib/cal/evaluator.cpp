#include "cal/evaluator.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace brume::cal {

// A user function's activation: its arguments are evaluated in the caller's frame when first used, as in
// Radiance (so `if` written as a user function still stops a recursion), and kept.
struct Evaluator::Frame {
    Frame(const uint32_t* args, uint32_t count, const Frame* caller) : args(args), count(count), caller(caller) {}

    const uint32_t* args;  // argument nodes; nullptr when the values were given
    uint32_t count;
    const Frame* caller;
    mutable uint32_t known = 0;  // bit i: values[i] holds argument i
    mutable double values[kMaxArgs];
};

// The most common nodes, without a call: constants, channels, variables already computed.
inline double Evaluator::eval(uint32_t index, const Frame* frame) {
    const Node& n = program_.nodes[index];
    if (n.op == Op::Const) return n.value;
    if (n.op == Op::Channel) return ray_.channels[n.ref];
    if (n.op == Op::Var && stamps_[n.ref] == epoch_) return values_[n.ref];
    return evalNode(n, frame);
}

Evaluator::Evaluator(const Program& program)
    : program_(program), stamps_(program.variables.size(), 0), values_(program.variables.size(), 0) {}

void Evaluator::begin(const Channels& channels, std::span<const double> args) {
    ray_ = {channels.data(), args};
    ++epoch_;
}

double Evaluator::operator()(ExprId e) { return evaluate(e.entry, nullptr); }

double Evaluator::operator()(FuncId f, std::span<const double> values) {
    const Program::Entry& entry = program_.entries[f.entry];
    if (values.size() < entry.params || values.size() > kMaxArgs)
        throw Error(entry.label + ": called with " + std::to_string(values.size()) + " arguments");
    Frame frame{nullptr, static_cast<uint32_t>(values.size()), nullptr};
    for (size_t i = 0; i < values.size(); ++i) frame.values[i] = values[i];
    frame.known = (1u << values.size()) - 1;
    return evaluate(f.entry, &frame);
}

double Evaluator::evaluate(uint32_t entry, const Frame* frame) {
    stack_ = StackDepth();
    calls_ = 0;
    double v;
    try {
        v = eval(program_.entries[entry].root, frame);
    } catch (...) {
        ++epoch_;  // forget values (and "being computed" marks) of the failed evaluation
        throw;
    }
    if (std::isfinite(v)) return v;
    warnOnce(program_.entries[entry].label + ": value is not a finite number, 0 used");
    return 0;
}

double Evaluator::evalNode(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    switch (n.op) {
        case Op::Const:
            return n.value;
        case Op::Channel:
            return ray_.channels[n.ref];
        case Op::Var:
            return variable(n);
        case Op::Param:
            return param(n.ref, frame);
        case Op::FuncRef:
            throw Error("a function name is used as a value");
        case Op::Negate:
            return -eval(kids[0], frame);
        case Op::Sum:
            return sum(n, frame);
        case Op::Product:
            return product(n, frame);
        case Op::Power:
            return power(n, frame);
        case Op::If:
            return eval(kids[eval(kids[0], frame) > 0 ? 1 : 2], frame);
        case Op::Select:
            return select(n, frame);
        case Op::Min:
            return extreme(n, frame, false);
        case Op::Max:
            return extreme(n, frame, true);
        case Op::Arg:
            return patternArgument(eval(kids[0], frame), ray_.args);
        case Op::Builtin:
            return callBuiltin(n.ref, kids, n.count, frame);
        case Op::Call:
            return call(n.ref, kids, n.count, frame);
        case Op::CallParam:
            return callParam(n, frame);
    }
    return 0;
}

double Evaluator::variable(const Node& n) {
    if (stamps_[n.ref] == epoch_) return values_[n.ref];
    const std::string& name = program_.variables[n.ref];
    if (stamps_[n.ref] == ~epoch_) throw Error(name + ": defined in terms of itself");
    if (stack_.bytes() > kMaxStackBytes) throw Error(name + ": definitions nested too deeply");
    stamps_[n.ref] = ~epoch_;
    double v = eval(program_.kids[n.kids], nullptr);
    values_[n.ref] = v;
    stamps_[n.ref] = epoch_;
    return v;
}

double Evaluator::param(uint32_t index, const Frame* frame) {
    bool cached = index < kMaxArgs;
    if (cached && (frame->known >> index & 1)) return frame->values[index];
    double v = eval(frame->args[index], frame->caller);
    if (cached) {
        frame->values[index] = v;
        frame->known |= 1u << index;
    }
    return v;
}

double Evaluator::call(uint32_t function, const uint32_t* args, uint32_t count, const Frame* frame) {
    const Program::Function& f = program_.functions[function];
    if (stack_.bytes() > kMaxStackBytes) throw Error(f.name + "(): recursion too deep");
    if (++calls_ > (folding_ ? kMaxFoldCalls : kMaxCalls)) {
        if (folding_) throw FoldFailure{};
        throw Error(f.name + "(): over " + std::to_string(kMaxCalls) + " calls in one evaluation");
    }
    Frame callee{args, count, frame};
    return eval(f.body, &callee);
}

double Evaluator::callBuiltin(uint32_t builtin, const uint32_t* args, uint32_t count, const Frame* frame) {
    const Builtin& f = *program_.builtins[builtin];
    uint32_t n = f.variadic ? count : f.arity;
    if (count < static_cast<uint32_t>(f.arity) || n > kMaxArgs)
        throw Error(std::string(f.name) + "(): wrong number of arguments");
    double a[kMaxArgs];
    for (uint32_t i = 0; i < n; ++i) a[i] = eval(args[i], frame);
    double v = f.fn(a, static_cast<int>(n), ray_);
    if (std::isfinite(v)) return v;
    return mathError((std::string(f.name) + (std::isnan(v) ? "(): domain error" : "(): range error")).c_str());
}

// The function a parameter stands for: the FuncRef its caller passed, following parameters passed on.
double Evaluator::callParam(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    uint32_t index = n.ref;
    for (const Frame* owner = frame;; owner = owner->caller) {
        if (!owner || !owner->args) throw Error("a parameter called as a function was not given a function");
        const Node& a = program_.nodes[owner->args[index]];
        if (a.op == Op::Param) {
            index = a.ref;
            continue;
        }
        if (a.op != Op::FuncRef) throw Error("a parameter called as a function was not given a function");
        if (a.ref & kBuiltinCallee) return callBuiltin(a.ref & ~kBuiltinCallee, kids, n.count, frame);
        const Program::Function& f = program_.functions[a.ref];
        if (n.count < f.params) throw Error(f.name + "(): too few arguments");
        return call(a.ref, kids, n.count, frame);
    }
}

double Evaluator::sum(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    double total = eval(kids[0] & ~kInverse, frame);
    for (uint32_t i = 1; i < n.count; ++i) {
        double v = eval(kids[i] & ~kInverse, frame);
        total = kids[i] & kInverse ? total - v : total + v;
    }
    return total;
}

double Evaluator::product(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    double total = eval(kids[0] & ~kInverse, frame);
    for (uint32_t i = 1; i < n.count; ++i) {
        double v = eval(kids[i] & ~kInverse, frame);
        if (!(kids[i] & kInverse))
            total *= v;
        else if (v != 0)
            total /= v;
        else
            total = mathError("division by zero");  // Radiance: the quotient is 0
    }
    return total;
}

double Evaluator::power(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    double base = eval(kids[0], frame);
    double v = std::pow(base, eval(kids[1], frame));
    return std::isfinite(v) ? v : mathError("illegal power");
}

double Evaluator::select(const Node& n, const Frame* frame) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    int k = selectIndex(eval(kids[0], frame), static_cast<int>(n.count) - 1);
    if (k < 0) return mathError("select(): domain error");
    return k == 0 ? n.count - 1 : eval(kids[k], frame);
}

double Evaluator::extreme(const Node& n, const Frame* frame, bool wantMax) {
    const uint32_t* kids = program_.kids.data() + n.kids;
    double best = eval(kids[0], frame);
    for (uint32_t i = 1; i < n.count; ++i) {
        double v = eval(kids[i], frame);
        best = wantMax ? std::max(best, v) : std::min(best, v);
    }
    return best;
}

double Evaluator::mathError(const char* what) {
    if (folding_) throw FoldFailure{};
    warnOnce(what);
    return 0;
}

double Evaluator::constantValue(uint32_t node) {
    folding_ = true;
    stack_ = StackDepth();
    calls_ = 0;
    double v = eval(node, nullptr);
    if (!std::isfinite(v)) throw FoldFailure{};
    return v;
}

}  // namespace brume::cal
