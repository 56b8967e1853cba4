#pragma once
// HLSL with what a declaration scanner must not read turned into spaces: comments, string
// literals and preprocessor lines. Newlines are kept, so offsets and line numbers still match.

#include <string>

namespace rmfx {

std::string blankedHlsl(const std::string& code);

}  // namespace rmfx
