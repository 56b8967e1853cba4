#pragma once
// The operands of each call of HLSL's mul() in a shader's code, as written: which side of mul a
// matrix stands on says which way round the code expects it (mul(M, v) is M·v, mul(v, M) is v·M).
// Comments, strings and preprocessor lines are skipped; calls nested in an operand are listed too.
// A call whose parentheses do not close, that does not have two operands, or with an operand
// longer than 256 characters is left out.

#include <map>
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

// What an operand is, as far as the code shows without compiling it.
enum class MulOperandShape { Vector, Matrix, Unknown };
// The names the code declares with a vector type (float2…float4, half4, int3…, vector) or a
// matrix type (float4x4, half3x3, matrix…), globals, parameters and locals alike; a name declared
// as both is left out.
std::map<std::string, MulOperandShape> declaredShapes(const std::string& code);
// A vector constructor (float4(…)) or cast, a member or swizzle (In.Pos, p.xyz), or a variable
// `declared` as a vector: Vector; a variable declared as a matrix, or a matrix cast: Matrix;
// anything else (a call such as mul(…), an element, arithmetic, a scalar): Unknown.
MulOperandShape mulOperandShape(std::string_view operand, const std::map<std::string, MulOperandShape>& declared);

// Each `float4x4 NAME = VALUE;` or `matrix NAME = VALUE;` (spaces as a regex's \s, the keyword a
// whole word, VALUE everything up to the next ';', which must come), in order, not overlapping:
// what the regex \b(?:float4x4|matrix)\s+(\w+)\s*=\s*([^;]*); finds, by a scan (libstdc++'s
// regex took 40 % of the rfx_import fuzz target's time under ASan). Views of `code`.
struct MatrixAssignment {
    std::string_view name, value;
};
std::vector<MatrixAssignment> matrixAssignments(std::string_view code);

}  // namespace rmfx
