#pragma once
// The shader stages of a pass, read from their files or inline text, includes expanded, with the
// built-in vertex shader where the pass gives none. Shared by validation and the GL executor so
// both compile exactly the same text.

#include <optional>
#include <string>
#include <vector>

#include "runtime/Diagnostic.h"
#include "runtime/ShaderPreprocessor.h"
#include "runtime/Workspace.h"

namespace rmfx {

struct PassStage {
    ShaderStage stage;
    PreprocessedShader shader;
    SourceLocation where;  // the <shader> element, or the <pass> for the built-in vertex shader
    bool builtin = false;
};

struct PassProgramSource {
    std::vector<PassStage> stages;  // vertex first
};

// Reads and preprocesses a pass's shaders. Missing files, include errors and a missing
// fragment shader are reported; returns nullopt when the program cannot be assembled.
std::optional<PassProgramSource> assemblePassProgram(const Workspace& ws, const Pass& pass,
                                                     const std::vector<std::string>& defines,
                                                     Diagnostics& diagnostics,
                                                     const std::vector<std::string>& declarations = {});

std::string passLabel(const Pass& pass);  // <pass name="…">

// The built-in vertex shaders. Both write vTexCoord, vWorldPosition and vWorldNormal.
const char* builtinFullscreenVertexShader();  // clip-space triangle; world position on the far plane
const char* builtinModelVertexShader();       // rm_Model, rm_ViewProjection, rm_NormalMatrix

}  // namespace rmfx
