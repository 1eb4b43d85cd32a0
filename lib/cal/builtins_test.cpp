#include "cal/builtins.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cal/testing.h"

namespace brume::cal {
namespace {

using testing::Calc;

struct Reference {
    const char* expr;
    double value;
};

// Values printed by Radiance 6.1's rcalc (rcalc -n -od -e '$1=expr'), to full double precision.
constexpr Reference kRcalc[] = {
    {"2^0.5^2", 1.189207115002721},
    {"sqrt(2)", 1.4142135623730951},
    {"exp(1.5)", 4.4816890703380645},
    {"log(10)", 2.302585092994046},
    {"log10(2)", 0.3010299956639812},
    {"sin(1)", 0.8414709848078965},
    {"cos(1)", 0.5403023058681398},
    {"tan(1)", 1.5574077246549023},
    {"asin(.5)", 0.5235987755982989},
    {"acos(.3)", 1.2661036727794992},
    {"atan(2)", 1.1071487177940904},
    {"atan2(1,-2)", 2.677945044588987},
    {"atan2(-1,-2)", -2.677945044588987},
    {"floor(-2.5)", -3},
    {"ceil(-2.5)", -2},
    {"min(3,1,2)", 1},
    {"max(3,1,2)", 3},
    {"select(2,5,6,7)", 6},
    {"select(0,5,6,7)", 3},
    {"select(2.4,5,6,7)", 6},
    {"select(2.6,5,6,7)", 7},
    {"if(0,1,2)", 2},
    {"if(1e-300,1,2)", 1},
    {"1.5e-3*2E2", 0.3},
    {".5+1.", 1.5},
    // Errors: rcalc warns and gives 0.
    {"sqrt(-1)", 0},
    {"log(0)", 0},
    {"1/0", 0},
    {"(-8)^(1/3)", 0},
    {"0^-1", 0},
    {"0^0", 1},
    {"acos(2)", 0},
    {"exp(1000)", 0},
    {"select(4,5,6,7)", 0},
};

TEST(CalBuiltins, ValuesMatchRadiancesRcalc) {
    Calc calc;
    for (const Reference& r : kRcalc) EXPECT_NEAR(calc(r.expr), r.value, 1e-15 * std::abs(r.value)) << r.expr;
}

TEST(CalBuiltins, ErfIsTheC99ErrorFunction) {
    Calc calc;
    EXPECT_DOUBLE_EQ(calc("erf(.5)"), std::erf(.5));
    EXPECT_DOUBLE_EQ(calc("erfc(.5)"), std::erfc(.5));
}

TEST(CalBuiltins, RandDependsOnlyOnItsArgumentAndStaysInTheUnitInterval) {
    Calc calc;
    // Radiance 6.1's rcalc -od: rand(3.5), rand(0), rand(-7.25), rand(1e6), rand(12345.678).
    EXPECT_DOUBLE_EQ(calc("rand(3.5)"), 0.6137482334743254);
    EXPECT_DOUBLE_EQ(calc("rand(0)"), 0.954473516496364);
    EXPECT_DOUBLE_EQ(calc("rand(-7.25)"), 0.9067064882692648);
    EXPECT_DOUBLE_EQ(calc("rand(1e6)"), 0.31236551299662096);
    EXPECT_DOUBLE_EQ(calc("rand(12345.678)"), 0.23139812686713412);
    EXPECT_EQ(calc("rand(3.5)"), calc("rand(3.5)"));
    EXPECT_NE(calc("rand(3.5)"), calc("rand(4.5)"));
    EXPECT_EQ(calc("rand(0)"), calc("rand(-0)"));
    double sum = 0;
    for (int i = 0; i < 1000; ++i) {
        double r = calc("rand(" + std::to_string(i) + ")");
        EXPECT_GE(r, 0);
        EXPECT_LT(r, 1);
        sum += r;
    }
    EXPECT_NEAR(sum / 1000, .5, .03);
}

TEST(CalBuiltins, PatternArgumentsAreNumberedFromOne) {
    std::vector<double> args{4, 5};
    EXPECT_EQ(patternArgument(0, args), 2);
    EXPECT_EQ(patternArgument(-3, args), 2);
    EXPECT_EQ(patternArgument(1.4, args), 4);
    EXPECT_EQ(patternArgument(1.6, args), 5);
    EXPECT_THROW(patternArgument(3, args), Error);
    EXPECT_THROW(patternArgument(NAN, args), Error);
    EXPECT_THROW(patternArgument(1e300, args), Error);
}

TEST(CalBuiltins, SelectIndexRoundsAndRefusesOutOfRange) {
    EXPECT_EQ(selectIndex(0, 3), 0);
    EXPECT_EQ(selectIndex(2.49, 3), 2);
    EXPECT_EQ(selectIndex(3.49, 3), 3);
    EXPECT_EQ(selectIndex(3.5, 3), -1);
    EXPECT_EQ(selectIndex(-.6, 3), -1);
    EXPECT_EQ(selectIndex(NAN, 3), -1);
    EXPECT_EQ(selectIndex(1e300, 3), -1);
}

TEST(CalBuiltins, TheTableIsSortedForLookUp) {
    for (const char* name : {"acos", "arg", "fnoise3", "if", "noise3z", "select", "source_theta", "tan"})
        EXPECT_NE(findBuiltin(name), nullptr) << name;
    EXPECT_EQ(findBuiltin("abs"), nullptr);  // defined in rayinit.cal
}

}  // namespace
}  // namespace brume::cal
