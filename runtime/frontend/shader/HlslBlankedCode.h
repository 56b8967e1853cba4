#pragma once
// HLSL with what a declaration scanner must not read turned into spaces: comments, string
// literals and preprocessor lines. Newlines are kept, so offsets and line numbers still match.

#include <string>

namespace rmfx {

std::string blankedHlsl(const std::string& code);

// Code blanked once for scanners that each read it (findHlslGlobalInitializers and
// giveWrittenGlobalsACopy over one text): blanking is a pass and a copy of the whole code, and a
// shader expanded to a mebibyte by its includes is read by each scanner in turn.
struct BlankedHlsl {
    explicit BlankedHlsl(const std::string& code) : text(blankedHlsl(code)) {}
    std::string text;
};

}  // namespace rmfx
