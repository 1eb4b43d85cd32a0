#include "cal/compiler.h"

#include <gtest/gtest.h>

#include <numbers>

#include "cal/testing.h"

namespace brume::cal {
namespace {

using testing::Calc;

// The root node of `expr` compiled with `definitions`.
Node root(std::string_view definitions, std::string_view expr) {
    testing::Build build(definitions);
    ExprId e = build.expr(expr);
    Program p = build.finish();
    return p.nodes[p.entries[e.entry].root];
}

TEST(CalCompiler, ConstantsFoldIntoOneNumber) {
    Node n = root("k : 2*PI; half(x) = x/2; big = half(k)^2 + sq(3);", "big + cos(PI) + select(2, 1, 2)");
    EXPECT_EQ(n.op, Op::Const);
    EXPECT_DOUBLE_EQ(n.value, std::numbers::pi * std::numbers::pi + 9 - 1 + 2);
}

TEST(CalCompiler, LeadingConstantsOfASumFoldExactly) {
    Node n = root("", "2*PI/180*Dx");
    ASSERT_EQ(n.op, Op::Product);
    EXPECT_EQ(n.count, 2u);
}

TEST(CalCompiler, WhatDependsOnTheRayIsNotFolded) {
    EXPECT_NE(root("f(x) = x + Dx;", "f(1)").op, Op::Const);
    EXPECT_NE(root("", "A1").op, Op::Const);
    EXPECT_NE(root("", "source_phi(90)").op, Op::Const);
}

TEST(CalCompiler, AConstantIfCompilesOnlyTheBranchTaken) {
    Calc calc;
    EXPECT_EQ(calc("if(1, 2, undefined_name)"), 2);
    EXPECT_EQ(calc("select(1, 2, undefined_name)"), 2);
}

TEST(CalCompiler, NamesBindWhenCompiledNotWhenDefined) {
    Calc calc;
    calc.library.loadText("y = x*2;", "a.cal");
    calc.library.loadText("x = 3;", "b.cal");
    EXPECT_EQ(calc("y"), 6);
    calc.library.loadText("x = 4;", "c.cal");
    EXPECT_EQ(calc("y"), 8);
}

TEST(CalCompiler, FilesLoadedBetweenCompilesCountForLaterOnes) {
    testing::Build build("x = 1; y = x + Dx;");
    ExprId before = build.expr("y");
    build.library.loadText("x = 10;", "later.cal");
    ExprId after = build.expr("y");
    EXPECT_EQ(build.evaluate({before, after}), (std::vector<double>{1, 10}));
}

TEST(CalCompiler, ALaterDefinitionReplacesAnEarlierOne) {
    EXPECT_EQ(Calc("x : 1; f(a) = a; x = 2; f(a, b) = a + b;")("x + f(1, 2)"), 5);
}

TEST(CalCompiler, AVariableMayShareItsNameWithABuiltIn) { EXPECT_EQ(Calc("max = 3;")("max(1, max)"), 3); }

TEST(CalCompiler, ExtraArgumentsAreIgnoredAsInRadiance) {
    EXPECT_EQ(Calc("f(x) = x;")("f(1, undefined_name) + sqrt(4, 5)"), 3);
}

TEST(CalCompiler, ErrorsNameTheNameAndWhereItIsUsed) {
    Calc calc("a = 1;\nb = a + nothing;\nf(x, y) = x;\nc = f(1);\nd = g(2);");
    EXPECT_EQ(calc.error("b"), "t.cal:2: undefined variable 'nothing'");
    EXPECT_EQ(calc.error("c"), "t.cal:4: f(): 2 arguments expected");
    EXPECT_EQ(calc.error("d"), "t.cal:5: undefined function 'g'");
    EXPECT_EQ(calc.error("a(1)"), "test:1: 'a' is a variable, not a function");
    EXPECT_EQ(calc.error("sqrt"), "test:1: undefined variable 'sqrt'");
    EXPECT_EQ(calc.error("atan2(1)"), "test:1: atan2(): 2 arguments expected");
    EXPECT_EQ(calc.error("$0 + $99"), "test:1: illegal channel number $0");
}

TEST(CalCompiler, AFailedCompileLeavesNothingHalfDone) {
    testing::Build build("n = nothing; m = n + 1; s(x) = r(x - 1); r(x) = if(x, s(x), undefined); ok = 2;");
    for (int attempt = 0; attempt < 2; ++attempt) {
        EXPECT_THROW(build.expr("m"), Error);
        EXPECT_THROW(build.expr("n"), Error);
        EXPECT_THROW(build.expr("s(1)"), Error);
    }
    EXPECT_EQ(build.evaluate({build.expr("ok + Dx")}), std::vector<double>{2});
}

TEST(CalCompiler, FunctionHandlesCheckTheirArguments) {
    Library library;
    Compiler compiler(library);
    auto error = [&](const char* name, int nargs) {
        try {
            compiler.function(name, nargs, {}, {"scene.rad", 3});
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("grey", 1), "scene.rad:3: grey: takes 3 arguments, not 1");
    EXPECT_EQ(error("atan2", 1), "scene.rad:3: atan2: takes 2 arguments");
    EXPECT_EQ(error("PI", 1), "scene.rad:3: PI: is a variable, not a function");
    EXPECT_EQ(error("nothing", 1), "scene.rad:3: nothing: undefined function");
    EXPECT_EQ(error("noop", 1), "no error");
}

TEST(CalCompiler, AConstantThatDependsOnTheRayIsEvaluatedPerRay) {
    // Radiance keeps the first ray's value (with a warning); Brume warns and evaluates it per ray.
    Calc calc("k : Dx*2;");
    calc.channels[Dx] = 1;
    EXPECT_EQ(calc("k"), 2);
    calc.channels[Dx] = 2;
    EXPECT_EQ(calc("k"), 4);
}

TEST(CalCompiler, ABadConstantIsLeftForEvaluationWhichGivesZero) {
    Calc calc;
    EXPECT_EQ(calc("if(Dx, sqrt(-1), 1/0)"), 0);
}

TEST(CalCompiler, LongChainsOfDefinitionsAreRefusedNotACrash) {
    Calc calc;
    std::string text;
    for (int i = 0; i < 10000; ++i) text += "v" + std::to_string(i) + " = v" + std::to_string(i + 1) + " + 1;\n";
    calc.library.loadText(text + "v10000 = Dx;", "t.cal");
    EXPECT_NE(calc.error("v0").find("definitions nested too deeply"), std::string::npos);
    EXPECT_EQ(calc("v9000"), 1000);
}

}  // namespace
}  // namespace brume::cal
