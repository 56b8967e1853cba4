#pragma once
// Where brackets in shader code are not nested properly: a closer that does not match the last
// opener ("T[a)"), or one with no opener. Debian's glslang crashes in its HLSL grammar on an
// unclosed '[' in a parameter list (`float3 T[a) : TEXCOORD0`; glslangValidator -V -D segfaults
// too), so HLSL is checked for this before glslang reads it. Comments and string literals are
// skipped; an opener left open at the end is not reported (glslang reports that itself).

#include <optional>
#include <string>
#include <string_view>

namespace rmfx {

struct BracketMismatch {
    int line = 0;  // 1-based line of the closer
    std::string message;
};

std::optional<BracketMismatch> findBracketMismatch(std::string_view code);

}  // namespace rmfx
