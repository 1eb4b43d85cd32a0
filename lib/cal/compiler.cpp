#include "cal/compiler.h"

#include <algorithm>

#include "cal/builtins.h"
#include "cal/channels.h"
#include "cal/evaluator.h"
#include "cal/parser.h"

namespace brume::cal {

namespace {

int paramIndex(const Definition* function, const std::string& name) {
    if (!function) return -1;
    auto it = std::find(function->params.begin(), function->params.end(), name);
    return it == function->params.end() ? -1 : static_cast<int>(it - function->params.begin());
}

// The built-ins with an operation of their own: lazy (if, select), variadic (min, max), or reading the
// pattern's arguments (arg).
Op opOf(const Builtin& b) {
    static constexpr std::pair<std::string_view, Op> kSpecial[] = {
        {"if", Op::If}, {"select", Op::Select}, {"min", Op::Min}, {"max", Op::Max}, {"arg", Op::Arg}};
    for (const auto& [name, op] : kSpecial)
        if (b.name == name) return op;
    return Op::Builtin;
}

}  // namespace

ExprId Compiler::expression(std::string_view text, const Scope& scope, const SourceLocation& where) {
    uint32_t root = transaction([&] {
        return compile(parseExpression(text, where), Site{scope.context, nullptr, where.file});
    });
    return {addEntry(root, 0, where.str() + ": " + std::string(text))};
}

FuncId Compiler::function(std::string_view name, int nargs, const Scope& scope, const SourceLocation& where) {
    std::string label = where.str() + ": " + std::string(name);
    if (nargs < 1 || nargs > static_cast<int>(Evaluator::kMaxArgs))
        throw Error(label + ": unsupported number of arguments");
    uint32_t root = transaction([&] { return functionRoot(name, nargs, scope, label); });
    return {addEntry(root, static_cast<uint32_t>(nargs), label)};
}

// A user function's body, or a built-in applied to the arguments.
uint32_t Compiler::functionRoot(std::string_view name, int nargs, const Scope& scope, const std::string& label) {
    const Definition* d = library_.find(name, scope);
    if (d && d->isFunction()) {
        if (d->params.size() > static_cast<size_t>(nargs))
            throw Error(label + ": takes " + std::to_string(d->params.size()) + " arguments, not " +
                        std::to_string(nargs));
        return program_.functions[functionIndex(*d)].body;
    }
    const Builtin* b = findBuiltin(name);
    if (!b) throw Error(label + (d ? ": is a variable, not a function" : ": undefined function"));
    if (b->arity > nargs) throw Error(label + ": takes " + std::to_string(b->arity) + " arguments");
    std::vector<uint32_t> params;
    for (int i = 0; i < (b->variadic ? nargs : b->arity); ++i)
        params.push_back(add(Node{.op = Op::Param, .ref = uint32_t(i)}));
    return add(Op::Builtin, params, builtinIndex(*b));
}

template <class F>
uint32_t Compiler::transaction(F&& compileRoot) {
    stack_ = StackDepth();
    if (library_.version() != libraryVersion_) {
        // Definitions changed: what was compiled stays for the entries that use it, but is not reused.
        variables_.clear();
        functions_.clear();
        libraryVersion_ = library_.version();
    }
    const size_t nodes = program_.nodes.size(), kids = program_.kids.size(), functions = program_.functions.size(),
                 variables = program_.variables.size(), builtins = program_.builtins.size();
    try {
        return compileRoot();
    } catch (...) {
        // Nothing half-compiled may stay behind for a later expression to use.
        std::erase_if(variables_, [&](const auto& v) { return v.second >= nodes; });
        std::erase_if(functions_, [&](const auto& f) { return f.second >= functions; });
        std::erase_if(builtins_, [&](const auto& b) { return b.second >= builtins; });
        program_.nodes.resize(nodes);
        program_.kids.resize(kids);
        program_.functions.resize(functions);
        pure_.resize(functions);
        program_.variables.resize(variables);
        program_.builtins.resize(builtins);
        throw;
    }
}

uint32_t Compiler::addEntry(uint32_t root, uint32_t params, std::string label) {
    program_.entries.push_back({root, params, std::move(label)});
    return static_cast<uint32_t>(program_.entries.size() - 1);
}

uint32_t Compiler::compile(const Expr& e, const Site& site) {
    if (stack_.bytes() > kMaxStackBytes) throw Error(at(e, site), "definitions nested too deeply");
    switch (e.kind) {
        case Expr::Kind::Number:
            return constant(e.number);
        case Expr::Kind::Channel:
            if (e.channel < 1 || e.channel >= kChannelCount)
                throw Error(at(e, site), "illegal channel number $" + std::to_string(e.channel));
            return add(Node{.op = Op::Channel, .ref = static_cast<uint32_t>(e.channel)});
        case Expr::Kind::Name:
            return name(e, site, false);
        case Expr::Kind::Call:
            return call(e, site);
        case Expr::Kind::Negate: {
            uint32_t kid = compile(e.kids[0], site);
            if (isConst(kid)) return constant(-program_.nodes[kid].value);
            return add(Op::Negate, {kid});
        }
        case Expr::Kind::Sum:
        case Expr::Kind::Product:
            return chain(e, site);
        case Expr::Kind::Power: {
            std::vector<uint32_t> kids = {compile(e.kids[0], site), compile(e.kids[1], site)};
            uint32_t node = add(Op::Power, kids);
            return allConst(kids) ? fold(node) : node;
        }
    }
    return 0;
}

// A user function's argument may also be the name of a function, which the function then calls.
uint32_t Compiler::compileArgument(const Expr& e, const Site& site) {
    return e.kind == Expr::Kind::Name ? name(e, site, true) : compile(e, site);
}

uint32_t Compiler::name(const Expr& e, const Site& site, bool functionAllowed) {
    if (int i = paramIndex(site.function, e.name); i >= 0) return add(Node{.op = Op::Param, .ref = uint32_t(i)});
    const Definition* d = library_.find(e.name, Scope{site.context});
    if (d && !d->isFunction()) return variableNode(*d);
    if (functionAllowed && d) return add(Node{.op = Op::FuncRef, .ref = functionIndex(*d)});
    if (const Builtin* b = findBuiltin(e.name); functionAllowed && b)
        return add(Node{.op = Op::FuncRef, .ref = kBuiltinCallee | builtinIndex(*b)});
    throw Error(at(e, site), "undefined variable '" + e.name + "'");
}

uint32_t Compiler::call(const Expr& e, const Site& site) {
    std::vector<uint32_t> kids;
    if (int i = paramIndex(site.function, e.name); i >= 0) {
        for (const Expr& a : e.kids) kids.push_back(compileArgument(a, site));
        return add(Op::CallParam, kids, static_cast<uint32_t>(i));
    }
    const Definition* d = library_.find(e.name, Scope{site.context});
    if (d && d->isFunction()) {
        if (e.kids.size() < d->params.size())
            throw Error(at(e, site), e.name + "(): " + std::to_string(d->params.size()) + " arguments expected");
        // Arguments beyond the parameters are never evaluated (as in Radiance).
        for (size_t k = 0; k < d->params.size(); ++k) kids.push_back(compileArgument(e.kids[k], site));
        uint32_t f = functionIndex(*d);
        uint32_t node = add(Op::Call, kids, f);
        return pure_[f] && allConst(kids) ? fold(node) : node;
    }
    // A variable may share its name with a built-in function (Radiance keeps them apart).
    if (const Builtin* b = findBuiltin(e.name)) return builtinCall(*b, e, site);
    throw Error(at(e, site),
                d ? "'" + e.name + "' is a variable, not a function" : "undefined function '" + e.name + "'");
}

uint32_t Compiler::builtinCall(const Builtin& b, const Expr& e, const Site& site) {
    if (e.kids.size() < static_cast<size_t>(b.arity))
        throw Error(at(e, site), e.name + "(): " + std::to_string(b.arity) + " arguments expected");
    std::vector<uint32_t> kids{compile(e.kids[0], site)};
    // if and select evaluate only the argument chosen; with a constant choice, only it is compiled.
    if (b.name == "if" && isConst(kids[0])) return compile(e.kids[program_.nodes[kids[0]].value > 0 ? 1 : 2], site);
    if (b.name == "select" && isConst(kids[0])) {
        int k = selectIndex(program_.nodes[kids[0]].value, static_cast<int>(e.kids.size()) - 1);
        if (k == 0) return constant(static_cast<double>(e.kids.size() - 1));
        if (k > 0) return compile(e.kids[k], site);
    }
    size_t used = b.variadic ? e.kids.size() : static_cast<size_t>(b.arity);
    for (size_t k = 1; k < used; ++k) kids.push_back(compile(e.kids[k], site));
    Op op = opOf(b);
    uint32_t node = add(op, kids, op == Op::Builtin ? builtinIndex(b) : 0);
    return !b.readsRay && allConst(kids) ? fold(node) : node;
}

// A Sum or Product: constant leading terms are combined (in the order written, so exactly).
uint32_t Compiler::chain(const Expr& e, const Site& site) {
    Op op = e.kind == Expr::Kind::Sum ? Op::Sum : Op::Product;
    std::vector<uint32_t> kids;
    for (size_t k = 0; k < e.kids.size(); ++k) {
        bool inverse = e.ops[k] == '-' || e.ops[k] == '/';
        kids.push_back(compile(e.kids[k], site) | (inverse ? kInverse : 0));
    }
    size_t leading = 0;
    while (leading < kids.size() && isConst(kids[leading] & ~kInverse)) ++leading;
    if (leading >= 2) {
        uint32_t prefix = fold(add(op, std::vector<uint32_t>(kids.begin(), kids.begin() + leading)));
        if (isConst(prefix)) {
            kids.erase(kids.begin(), kids.begin() + leading);
            kids.insert(kids.begin(), prefix);
        }
    }
    return kids.size() == 1 ? kids[0] : add(op, kids);
}

// A variable: its memo slot, or its definition itself when that is as cheap as a memo look-up (a
// constant, a channel, a real argument such as A1 = arg(1)).
uint32_t Compiler::variableNode(const Definition& d) {
    if (auto it = variables_.find(&d); it != variables_.end()) return it->second;  // done, or in a cycle
    uint32_t var = add(Node{.op = Op::Var, .ref = static_cast<uint32_t>(program_.variables.size())});
    program_.variables.push_back(d.name);
    variables_[&d] = var;
    uint32_t body = compile(d.body, Site{d.context, nullptr, d.where.file});
    const Node& b = program_.nodes[body];
    Op op = b.op;
    if (op == Op::Const || op == Op::Channel || (op == Op::Arg && isConst(program_.kids[b.kids]))) {
        program_.nodes[var] = program_.nodes[body];
    } else {
        program_.nodes[var].kids = static_cast<uint32_t>(program_.kids.size());
        program_.nodes[var].count = 1;
        program_.kids.push_back(body);
    }
    if (d.constant && op != Op::Const)
        warn(d.where.str() + ": " + d.name + ": assigned non-constant value (evaluated per ray)");
    return var;
}

uint32_t Compiler::functionIndex(const Definition& d) {
    if (auto it = functions_.find(&d); it != functions_.end()) return it->second;
    uint32_t f = static_cast<uint32_t>(program_.functions.size());
    program_.functions.push_back({d.name, 0, static_cast<uint32_t>(d.params.size())});
    pure_.push_back(false);
    functions_[&d] = f;
    uint32_t body = compile(d.body, Site{d.context, &d, d.where.file});
    program_.functions[f].body = body;
    pure_[f] = !dependsOnRay(body);
    return f;
}

uint32_t Compiler::builtinIndex(const Builtin& b) {
    auto [it, added] = builtins_.try_emplace(&b, static_cast<uint32_t>(program_.builtins.size()));
    if (added) program_.builtins.push_back(&b);
    return it->second;
}

uint32_t Compiler::add(Node n) {
    program_.nodes.push_back(n);
    return static_cast<uint32_t>(program_.nodes.size() - 1);
}

uint32_t Compiler::add(Op op, const std::vector<uint32_t>& kids, uint32_t ref) {
    Node n{.op = op,
           .kids = static_cast<uint32_t>(program_.kids.size()),
           .count = static_cast<uint32_t>(kids.size()),
           .ref = ref};
    program_.kids.insert(program_.kids.end(), kids.begin(), kids.end());
    return add(n);
}

bool Compiler::allConst(const std::vector<uint32_t>& kids) const {
    return std::all_of(kids.begin(), kids.end(), [&](uint32_t k) { return isConst(k & ~kInverse); });
}

uint32_t Compiler::fold(uint32_t node) {
    try {
        double v = Evaluator(program_).constantValue(node);
        program_.nodes[node] = Node{.op = Op::Const, .value = v};
    } catch (const Evaluator::FoldFailure&) {
        // Left for evaluation, which gives 0 and a warning if it is ever reached.
    } catch (const Error&) {
        // e.g. recursion too deep: reported if it is ever reached.
    }
    return node;
}

// Whether the node's value may change with the channels or the pattern's arguments (a variable that
// is still a variable after folding does).
bool Compiler::dependsOnRay(uint32_t index) const {
    const Node& n = program_.nodes[index];
    switch (n.op) {
        case Op::Channel:
        case Op::Var:
        case Op::Arg:
        case Op::CallParam:
            return true;
        case Op::Call:
            if (!pure_[n.ref]) return true;
            break;
        case Op::Builtin:
            if (program_.builtins[n.ref]->readsRay) return true;
            break;
        default:
            break;
    }
    for (uint32_t k = 0; k < n.count; ++k)
        if (dependsOnRay(program_.kids[n.kids + k] & ~kInverse)) return true;
    return false;
}

}  // namespace brume::cal
