#pragma once
// The operands of each call of HLSL's mul() in a shader's code, as written: which side of mul a
// matrix stands on says which way round the code expects it (mul(M, v) is M·v, mul(v, M) is v·M).
// Comments, strings and preprocessor lines are skipped; calls nested in an operand are listed too.
// A call whose parentheses do not close, or that does not have two operands, is left out.

#include <string>
#include <string_view>
#include <vector>

namespace rmfx {

struct MulCall {
    int line = 0;  // 1-based, of the word mul
    std::string first, second;
};

std::vector<MulCall> mulCalls(const std::string& code);

// The variable an operand names: a plain identifier, optionally in parentheses, behind a cast
// ("(float3x3) World") or inside transpose(); empty for anything else (a call, a member, an
// element, arithmetic). `transposed`: it was inside transpose().
struct MulOperandVariable {
    std::string name;
    bool transposed = false;
};
MulOperandVariable mulOperandVariable(std::string_view operand);

}  // namespace rmfx
