#pragma once
// The integer expression of an `#if` or `#elif` in a ReShade FX file, once its macros are expanded
// and `defined X` / `exists "file"` are replaced by 1 or 0 (ReshadePreprocessor.h does both).
//
//   evaluateExpression(tokenize("(1 << 4) + 0x10 == 32 && !UNKNOWN ? 7 : 8")) → 7
//
// As C's preprocessor: 64-bit signed arithmetic, every C operator (unary + - ! ~, * / %, + -,
// << >>, < <= > >=, == !=, &, ^, |, &&, ||, ?:), parentheses, decimal, hex (0x) and octal (leading
// 0) numbers with u/l suffixes, character literals, and an identifier that is left is 0. ReShade's
// own evaluator computes in 32 bits and has no ?:; the version and size checks effects make read
// the same in both.

#include <cstdint>
#include <string>

#include "frontend/reshade/ReshadeTokens.h"

namespace rmfx {

struct ExpressionValue {
    int64_t value = 0;
    std::string error;  // why there is no value: "division by zero", "expected ')'", …; empty when there is one
};

ExpressionValue evaluateExpression(const PpTokens& tokens);

}  // namespace rmfx
