// Parsing the .cal language (Radiance's calexpr.c/caldefn.c grammar):
//
//   file       := { ';' | definition (';' | end) }
//   definition := name [ '(' param {',' param} ')' ] ('=' | ':') sum
//   sum        := product { ('+' | '-') product }                    left associative
//   product    := power { ('*' | '/') power }                         left associative
//   power      := unary [ '^' power ]                                 right associative
//   unary      := ('-' | '+') primary | primary                       so -2^2 is (-2)^2 = 4
//   primary    := number | '$' digits | name | name '(' sum {',' sum} ')' | '(' sum ')'
#pragma once
#include <string_view>
#include <vector>

#include "cal/expression.h"

namespace brume::cal {

// The definitions of a .cal file (or text); `file` and the line numbers name them in messages.
std::vector<Definition> parseDefinitions(std::string_view text, const std::string& file, int firstLine = 1);

// One expression, e.g. a pattern's argument ("src_phi2+90"); errors name `where`.
Expr parseExpression(std::string_view text, const SourceLocation& where);

// Deeper nesting (parentheses, calls, powers) is refused rather than risking the stack.
constexpr int kMaxNesting = 1000;

}  // namespace brume::cal
