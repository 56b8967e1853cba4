#pragma once
// Whether shader code names an identifier: a whole-word match, not a substring ("Ke" is not in
// "Kernel"). Comments and strings are not told apart; good enough to say what code uses.

#include <string_view>

namespace rmfx {

bool mentionsIdentifier(std::string_view code, std::string_view name);

// Whether GLSL code declares a vertex input `name`: a statement holding the word `attribute` or
// `in` before the name, which ends it (";", "," or "["). No regex: shaders can be long.
bool declaresVertexInput(std::string_view code, std::string_view name);

}  // namespace rmfx
