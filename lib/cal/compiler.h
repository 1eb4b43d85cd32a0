// Compiling .cal expressions into a Program: names resolved (late binding: a definition made before the
// compile counts, wherever it appears), constants folded, each variable given a memo slot.
#pragma once
#include <string_view>
#include <unordered_map>

#include "cal/library.h"
#include "cal/program.h"
#include "cal/stack_depth.h"

namespace brume::cal {

// Compile every expression a scene needs, then take the Program and share it between threads, each with
// its own Evaluator. Files may be loaded into the Library between compiles: each expression uses the
// definitions there are when it is compiled.
//
// Everything that depends neither on the channels nor on the pattern's arguments is folded into a
// constant (':' definitions included), so evaluation only does per-ray work. An undefined name is an
// error here, naming the name and where it was used.
class Compiler {
public:
    explicit Compiler(const Library& library) : library_(library) {}

    // A pattern's expression (its function name, or a coordinate such as "src_phi2+90"), with names as
    // seen from `scope`. Errors name `where`.
    ExprId expression(std::string_view text, const Scope& scope, const SourceLocation& where);
    // The function `name` (defined in a .cal file, or built in) as seen from `scope`, to be called with
    // `nargs` numeric arguments (e.g. a data pattern's function of the interpolated value).
    FuncId function(std::string_view name, int nargs, const Scope& scope, const SourceLocation& where);

    Program finish() && { return std::move(program_); }

private:
    // Where names of an expression are resolved.
    struct Site {
        const std::string& context;
        const Definition* function;  // whose parameters are in scope, or nullptr
        const std::string& file;
    };

    // Compiles an entry's root; if that fails, undoes everything it added.
    template <class F>
    uint32_t transaction(F&& compileRoot);
    uint32_t functionRoot(std::string_view name, int nargs, const Scope& scope, const std::string& label);
    uint32_t addEntry(uint32_t root, uint32_t params, std::string label);
    uint32_t compile(const Expr& e, const Site& site);
    uint32_t compileArgument(const Expr& e, const Site& site);
    uint32_t name(const Expr& e, const Site& site, bool functionAllowed);
    uint32_t call(const Expr& e, const Site& site);
    uint32_t builtinCall(const Builtin& b, const Expr& e, const Site& site);
    uint32_t chain(const Expr& e, const Site& site);
    uint32_t variableNode(const Definition& d);
    uint32_t functionIndex(const Definition& d);
    uint32_t builtinIndex(const Builtin& b);

    uint32_t add(Node n);
    uint32_t add(Op op, const std::vector<uint32_t>& kids, uint32_t ref = 0);
    uint32_t constant(double v) { return add(Node{.op = Op::Const, .value = v}); }
    bool isConst(uint32_t node) const { return program_.nodes[node].op == Op::Const; }
    bool allConst(const std::vector<uint32_t>& kids) const;
    // The node turned into its constant value, if evaluating it has no math error.
    uint32_t fold(uint32_t node);
    bool dependsOnRay(uint32_t node) const;
    SourceLocation at(const Expr& e, const Site& site) const { return {site.file, e.line}; }

    const Library& library_;
    Program program_;
    std::unordered_map<const Definition*, uint32_t> variables_;  // definition -> its node
    std::unordered_map<const Definition*, uint32_t> functions_;  // definition -> Program::functions index
    std::vector<bool> pure_;  // per function: folds with constant arguments (false while being compiled)
    std::unordered_map<const Builtin*, uint32_t> builtins_;
    uint64_t libraryVersion_ = 0;  // of the definitions variables_ and functions_ were compiled from
    StackDepth stack_;
};

}  // namespace brume::cal
