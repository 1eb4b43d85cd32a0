// The parse tree of the .cal language: expressions and the definitions that name them.
#pragma once
#include <string>
#include <vector>

#include "util/error.h"

namespace brume::cal {

struct Expr {
    enum class Kind : unsigned char {
        Number,   // number
        Channel,  // $channel
        Name,     // a variable, or a function parameter
        Call,     // name(kids...)
        Negate,   // -kids[0]
        Sum,      // kids combined left to right with ops '+' / '-'
        Product,  // kids combined left to right with ops '*' / '/'
        Power,    // kids[0] ^ kids[1]
    };
    Kind kind = Kind::Number;
    int line = 0;
    double number = 0;
    int channel = 0;
    std::string name;
    std::vector<Expr> kids;
    // For Sum and Product, the operator before each kid (the first one's is '+' or '*'). Keeping a
    // chain as one node keeps long sums shallow and evaluates them in the order written.
    std::vector<char> ops;
};

// `name = body;` (a variable, evaluated once per ray) or `name : body;` (a constant), possibly with
// parameters: `name(a, b) = body;`.
struct Definition {
    std::string name;                 // as written
    std::vector<std::string> params;  // empty for a variable
    bool constant = false;            // ':' rather than '='
    Expr body;
    SourceLocation where;
    std::string context;  // the context its names resolve in (see Library)

    bool isFunction() const { return !params.empty(); }
};

// Same shape and values (the places they come from aside): redefining a name with an equal definition
// is not worth a warning.
bool sameExpr(const Expr& a, const Expr& b);

}  // namespace brume::cal
