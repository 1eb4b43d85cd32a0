#include "cal/parser.h"

#include <gtest/gtest.h>

namespace brume::cal {
namespace {

std::string syntaxError(const std::string& text) {
    try {
        parseDefinitions(text, "f.cal");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(CalParser, DefinitionsAreVariablesConstantsAndFunctions) {
    auto defs = parseDefinitions("a = 1; b : 2;\n f(x, y) = x; g(u) : u;", "f.cal");
    ASSERT_EQ(defs.size(), 4u);
    EXPECT_EQ(defs[0].name, "a");
    EXPECT_FALSE(defs[0].constant);
    EXPECT_TRUE(defs[1].constant);
    EXPECT_EQ(defs[2].params, (std::vector<std::string>{"x", "y"}));
    EXPECT_TRUE(defs[3].constant && defs[3].isFunction());
    EXPECT_EQ(defs[2].where.str(), "f.cal:2");
}

TEST(CalParser, EmptyStatementsAndAMissingFinalSemicolonAreAccepted) {
    EXPECT_EQ(parseDefinitions(";; a = 1;; b = 2", "f.cal").size(), 2u);
    EXPECT_TRUE(parseDefinitions("  { only a comment }  ", "f.cal").empty());
}

TEST(CalParser, ChainsOfSumsAndProductsAreOneNodeInWrittenOrder) {
    Expr e = parseExpression("a - b + c*d/e", {});
    ASSERT_EQ(e.kind, Expr::Kind::Sum);
    EXPECT_EQ(e.ops, (std::vector<char>{'+', '-', '+'}));
    ASSERT_EQ(e.kids[2].kind, Expr::Kind::Product);
    EXPECT_EQ(e.kids[2].ops, (std::vector<char>{'*', '*', '/'}));
}

TEST(CalParser, UnaryMinusBindsTighterThanPower) {
    // Radiance's grammar: E3 -> E4 ^ E3, E4 -> -E5, so -2^2 is (-2)^2.
    Expr e = parseExpression("-2^2", {});
    ASSERT_EQ(e.kind, Expr::Kind::Power);
    EXPECT_EQ(e.kids[0].number, -2);
    Expr n = parseExpression("-x^2", {});
    ASSERT_EQ(n.kind, Expr::Kind::Power);
    EXPECT_EQ(n.kids[0].kind, Expr::Kind::Negate);
}

TEST(CalParser, PowerIsRightAssociative) {
    Expr e = parseExpression("a^b^c", {});
    ASSERT_EQ(e.kind, Expr::Kind::Power);
    EXPECT_EQ(e.kids[0].name, "a");
    EXPECT_EQ(e.kids[1].kind, Expr::Kind::Power);
}

TEST(CalParser, NumbersFollowRadianceSyntax) {
    EXPECT_EQ(parseExpression("1.", {}).number, 1);
    EXPECT_EQ(parseExpression(".5", {}).number, .5);
    EXPECT_EQ(parseExpression("1.5E-2", {}).number, .015);
    EXPECT_EQ(parseExpression("2e+3", {}).number, 2000);
    EXPECT_EQ(parseExpression("1e-400", {}).number, 0);
}

TEST(CalParser, NamesMayHoldDotsUnderscoresAndContextMarks) {
    EXPECT_EQ(parseExpression("un2`P.", {}).name, "un2`P.");
    EXPECT_EQ(parseExpression("`local_x.1", {}).name, "`local_x.1");
    EXPECT_EQ(parseExpression("$ 12", {}).channel, 12);
}

TEST(CalParser, NestedCommentsCountAsSpaceAndLines) {
    auto defs = parseDefinitions("{ a { nested } comment\n}\na = { inline } 1;", "f.cal");
    ASSERT_EQ(defs.size(), 1u);
    EXPECT_EQ(defs[0].where.line, 3);
}

TEST(CalParser, CallsTakeExpressionsAsArguments) {
    Expr e = parseExpression("f(1, g(x)+2, (3))", {});
    ASSERT_EQ(e.kind, Expr::Kind::Call);
    EXPECT_EQ(e.name, "f");
    EXPECT_EQ(e.kids.size(), 3u);
}

TEST(CalParser, SyntaxErrorsNameFileLineAndTheToken) {
    EXPECT_EQ(syntaxError("a = 1;\nb = 2 c = 3;"), "f.cal:2: ';' expected, found 'c'");
    EXPECT_EQ(syntaxError("a = (1 + 2;"), "f.cal:1: ')' expected, found ';'");
    EXPECT_EQ(syntaxError("a = 1 +;"), "f.cal:1: expression expected, found ';'");
    EXPECT_EQ(syntaxError("a = --1;"), "f.cal:1: expression expected, found '-'");
    EXPECT_EQ(syntaxError("a = .;"), "f.cal:1: badly formed number, found '.'");
    EXPECT_EQ(syntaxError("a = 2e;"), "f.cal:1: missing exponent in number, found '2e'");
    EXPECT_EQ(syntaxError("a = 1e999;"), "f.cal:1: number out of range, found '1e999'");
    EXPECT_EQ(syntaxError("a = $;"), "f.cal:1: channel number expected after '$', found '$'");
    EXPECT_EQ(syntaxError("a = 1 # 2;"), "f.cal:1: ';' expected, found '#'");
    EXPECT_EQ(syntaxError("1 = a;"), "f.cal:1: name of a definition expected, found '1'");
    EXPECT_EQ(syntaxError("f(`x) = 1;"), "f.cal:1: parameter name expected, found '`x'");
    EXPECT_EQ(syntaxError("f(x = 1;"), "f.cal:1: ')' expected, found '='");
    EXPECT_EQ(syntaxError("a 1;"), "f.cal:1: '=' or ':' expected, found '1'");
    EXPECT_EQ(syntaxError("$1 = 2;"), "f.cal:1: channel assignments are for rcalc, not a renderer, found '$1'");
    EXPECT_EQ(syntaxError("a = 1;\n{ open\n\n"), "f.cal:2: comment '{' is never closed");
    EXPECT_EQ(syntaxError("a = \x01;"), "f.cal:1: expression expected, found character code 1");
}

TEST(CalParser, ExpressionErrorsNameTheirOrigin) {
    try {
        parseExpression("src_phi2 +", {"scene.rad", 12});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "scene.rad:12: expression expected, found end of text");
    }
}

TEST(CalParser, DeepNestingIsRefusedNotACrash) {
    std::string deep = "a = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";";
    EXPECT_EQ(syntaxError(deep), "f.cal:1: expression nested too deeply, found '('");
    std::string powers = "a = 2";
    for (int i = 0; i < 5000; ++i) powers += "^2";
    EXPECT_EQ(syntaxError(powers), "f.cal:1: expression nested too deeply, found '^'");
    std::string longSum = "a = 0";
    for (int i = 0; i < 100000; ++i) longSum += "+1";
    EXPECT_EQ(syntaxError(longSum), "no error");
}

}  // namespace
}  // namespace brume::cal
