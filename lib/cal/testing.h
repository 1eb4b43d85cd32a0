// For the cal unit tests: compile and evaluate expressions in one call.
#pragma once
#include <string>
#include <vector>

#include "cal/compiler.h"
#include "cal/evaluator.h"

namespace brume::cal::testing {

// A Library plus the channels and pattern arguments to evaluate with.
struct Calc {
    Calc() = default;
    // With `definitions` loaded, in the global context, from "t.cal".
    explicit Calc(std::string_view definitions) { library.loadText(definitions, "t.cal"); }

    Library library;
    Channels channels{};
    std::vector<double> args;

    // The value of `expr` as seen from `scope`, compiled afresh with the library as it is now.
    double operator()(const std::string& expr, const Scope& scope = {}) {
        Compiler compiler(library);
        ExprId e = compiler.expression(expr, scope, {"test", 1});
        Program program = std::move(compiler).finish();
        Evaluator evaluator(program);
        evaluator.begin(channels, args);
        return evaluator(e);
    }

    // The message of the brume::Error compiling or evaluating `expr` throws, or "no error".
    std::string error(const std::string& expr, const Scope& scope = {}) {
        try {
            (*this)(expr, scope);
        } catch (const Error& e) {
            return e.what();
        }
        return "no error";
    }
};

// Definitions compiled into a Program, for tests that keep their own Evaluator.
struct Build {
    explicit Build(std::string_view definitions) { library.loadText(definitions, "t.cal"); }
    ExprId expr(std::string_view text) { return compiler.expression(text, {}, {}); }
    FuncId func(std::string_view name, int nargs) { return compiler.function(name, nargs, {}, {}); }
    Program finish() { return std::move(compiler).finish(); }
    // Finishes the program and evaluates `exprs` for one ray with every channel 0.
    std::vector<double> evaluate(std::initializer_list<ExprId> exprs) {
        Program program = finish();
        Evaluator evaluator(program);
        Channels channels{};
        evaluator.begin(channels);
        std::vector<double> values;
        for (ExprId e : exprs) values.push_back(evaluator(e));
        return values;
    }

    Library library;
    Compiler compiler{library};
};

}  // namespace brume::cal::testing
