#pragma once
// Where brackets in shader code are not nested properly: a closer that does not match the last
// opener ("T[a)"), one with no opener, or an opener never closed. Debian's glslang crashes in its
// HLSL grammar on an unclosed '[' in a parameter list (`float3 T[a) : TEXCOORD0`) and on one left
// open at the end (`struct{float T;}o[`); glslangValidator -V -D segfaults on both. So HLSL is
// checked for this before glslang reads it. Comments and string literals are skipped.

#include <optional>
#include <string>
#include <string_view>

namespace rmfx {

struct BracketMismatch {
    int line = 0;  // 1-based line of the closer, or of an opener never closed
    std::string message;
};

std::optional<BracketMismatch> findBracketMismatch(std::string_view code);

}  // namespace rmfx
