#pragma once
// The shader stages of a pass, read from their files or inline text, includes expanded, with the
// built-in vertex shader where the pass gives none. Shared by validation and the GL executor so
// both compile exactly the same text.

#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "model/Workspace.h"

namespace rmfx {

struct PassStage {
    ShaderStage stage;
    PreprocessedShader shader;
    SourceLocation where;  // the <shader> element, or the <pass> for the built-in vertex shader
    bool builtin = false;
    ShaderDialect dialect = ShaderDialect::Glsl;  // of the code as compiled (Hlsl arrives translated)
};

struct PassProgramSource {
    std::vector<PassStage> stages;  // vertex first
};

// Reads and preprocesses a pass's shaders (HLSL translated to GLSL), with any warnings; fails
// naming missing files, include errors, a missing fragment shader, HLSL that does not translate.
Result<PassProgramSource> assemblePassProgram(const Workspace& ws, const Pass& pass,
                                              const std::vector<std::string>& defines,
                                              const std::vector<std::string>& declarations = {});

std::string passLabel(const Pass& pass);  // <pass name="…">

// The built-in vertex shaders, in the dialect of the fragment shader they run with (GlslLegacy:
// GLSL 1.10, which also sets gl_TexCoord[0]; GlslEs100: GLSL ES 1.00; else GLSL 4.50). Both write
// vTexCoord, vWorldPosition and vWorldNormal from the attributes rm_Position, rm_NormalIn and
// rm_TexCoordIn (locations 0, 1, 2: builtinAttributeLocations).
std::string builtinFullscreenVertexShader(ShaderDialect dialect = ShaderDialect::Glsl);  // clip-space triangle; world position on the far plane
std::string builtinModelVertexShader(ShaderDialect dialect = ShaderDialect::Glsl);  // rm_Model, rm_ViewProjection, rm_NormalMatrix

// The attribute names of the built-in vertex shaders and rmfx's mesh layout, by location; the GL
// executor binds them before linking, so that dialects without layout qualifiers get the same.
inline constexpr const char* builtinAttributeLocations[3] = {"rm_Position", "rm_NormalIn", "rm_TexCoordIn"};

}  // namespace rmfx
