#pragma once
// Reads Direct3D 9 shader assembly (the text RenderMonkey's RmShader holds) into a d3dasm::Program.
// Comments (`;`, `//`, `/* */`), the version token with dots or underscores (vs.1.1, ps_2_0),
// co-issue `+`, instruction modifiers, source modifiers, swizzles and write masks, and simple
// object-like `#define NAME text` (fxc ran the C preprocessor over assembly). Hand-written
// scanning: std::regex overflowed the stack under ASan on long input.

#include <string>
#include <vector>

#include "frontend/shader/D3DAsmProgram.h"

namespace rmfx::d3dasm {

struct ParseResult {
    Program program;
    std::vector<Message> messages;  // errors name the line and the instruction
    bool ok() const;
};

ParseResult parseAssembly(const std::string& code);

}  // namespace rmfx::d3dasm
