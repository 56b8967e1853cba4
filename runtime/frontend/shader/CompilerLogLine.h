#pragma once
// One line of a GLSL compiler's info log, in the styles rmfx meets:
//   glslang: "ERROR: 0:12: 'x' : undeclared identifier"
//   Mesa:    "0:12(5): error: `x' undeclared"
//   NVIDIA:  "0(12) : error C1008: undefined variable "x""
// Parsed by hand, not with std::regex: libstdc++'s regex recurses once per character and
// overflows the stack on a long line.

#include <optional>
#include <string_view>

namespace rmfx {

struct CompilerLogLine {
    bool error = true;           // else a warning
    std::string_view lineDigits;  // the shader line number as written (may exceed an int)
    std::string_view message;    // the rest, leading white space dropped
};

// nullopt when the line has none of the three forms; the views are into `line`.
std::optional<CompilerLogLine> parseCompilerLogLine(std::string_view line);

}  // namespace rmfx
