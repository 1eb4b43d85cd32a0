// Compiled .cal expressions: an immutable array of nodes, shared read-only by every thread's Evaluator.
// Built by a Compiler from a Library; names are resolved and constants folded, so evaluation does no
// look-ups and no allocation.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace brume::cal {

// Handles to what a Compiler compiled: an expression, or a function called with numeric arguments.
struct ExprId {
    uint32_t entry = 0;
};
struct FuncId {
    uint32_t entry = 0;
};

enum class Op : uint8_t {
    Const,      // value
    Channel,    // $ref
    Var,        // variable with memo slot ref; kid 0 is its definition
    Param,      // parameter ref of the function being evaluated
    FuncRef,    // a function passed by name as an argument: ref as for Call, or kBuiltinCallee | ref as for Builtin
    Negate,     // -kid
    Sum,        // kids added or, when marked kInverse, subtracted, left to right
    Product,    // kids multiplied or, when marked kInverse, divided, left to right
    Power,      // kid0 ^ kid1
    If,         // kid0 > 0 ? kid1 : kid2, evaluating only one branch
    Select,     // kid(round(kid0)), evaluating only that one
    Min,        // smallest kid
    Max,        // largest kid
    Arg,        // the pattern's real argument number kid0
    Builtin,    // built-in Program::builtins[ref] of its kids
    Call,       // Program::functions[ref] with the kids as arguments, each evaluated when first used
    CallParam,  // the function passed as parameter ref, called with the kids
};

struct Node {
    Op op = Op::Const;
    uint32_t kids = 0;   // index of the first kid in Program::kids
    uint32_t count = 0;  // number of kids
    uint32_t ref = 0;    // channel, slot, parameter, or callee, by op
    double value = 0;    // Const
};

constexpr uint32_t kBuiltinCallee = 1u << 31;
// In Program::kids: this kid is subtracted (Sum) or divides (Product).
constexpr uint32_t kInverse = 1u << 31;

struct Builtin;

struct Program {
    struct Function {
        std::string name;
        uint32_t body = 0;
        uint32_t params = 0;
    };
    // What a handle evaluates: a root node and, for a FuncId, the number of numeric arguments it takes.
    struct Entry {
        uint32_t root = 0;
        uint32_t params = 0;
        std::string label;  // for messages: "file:line: text"
    };

    std::vector<Node> nodes;
    std::vector<uint32_t> kids;
    std::vector<Function> functions;
    std::vector<const Builtin*> builtins;
    std::vector<Entry> entries;
    std::vector<std::string> variables;  // the name of each memo slot (Var's ref)
};

}  // namespace brume::cal
