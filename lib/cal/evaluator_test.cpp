#include "cal/evaluator.h"

#include <gtest/gtest.h>

#include "cal/compiler.h"

namespace brume::cal {
namespace {

double value(const std::string& defs, const std::string& expr) {
    Library lib;
    lib.loadText(defs, "t.cal");
    Compiler c(lib);
    ExprId e = c.expression(expr, {}, {"t.rad", 1});
    Program p = std::move(c).finish();
    Evaluator ev(p);
    Channels ch{};
    ev.begin(ch);
    return ev(e);
}

TEST(CalEvaluator, Smoke) {
    EXPECT_EQ(value("", "1+2*3"), 7);
    EXPECT_EQ(value("", "-2^2"), 4);
    EXPECT_EQ(value("f(x) = if(x, x*f(x-1), 1);", "f(5)"), 120);
}

}  // namespace
}  // namespace brume::cal
