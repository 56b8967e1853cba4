#pragma once
// Compiles and links a pass's GLSL with glslang, without any GL context, to report errors with
// portable messages and to list the active uniforms with their types.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/shader/PassProgram.h"
#include "model/UniformType.h"

namespace rmfx {

struct ActiveUniform {
    std::string name;
    UniformType type = UniformType::Other;
    int arraySize = 1;
    int glType = 0;
};

// Returns the active uniforms, or the diagnostics of the stage that fails to compile or of the link.
// With `vertexInputs`, also the names of the active vertex shader inputs (attributes).
Result<std::vector<ActiveUniform>> checkPassProgram(const PassProgramSource& program, const std::string& element,
                                                    std::vector<std::string>* vertexInputs = nullptr);

// The stage's text after glslang's preprocessor (macros expanded, #if resolved, #define lines
// gone), or the preprocessor's log: two texts that preprocess alike compile alike.
Result<std::string> preprocessStage(const PassStage& stage);

// Where a uniform is declared, found by scanning the stage texts: the first `uniform TYPE NAME`.
std::optional<SourceLocation> findUniformDeclaration(const PassProgramSource& program, const std::string& name);

// The uniforms the stage texts declare with an initial value (`uniform float k = 0.5;`, which the
// HLSL translator writes for initialised globals): left unbound, they keep that value.
std::set<std::string> uniformsWithInitializers(const PassProgramSource& program);

// Whether the active uniform `name` ("k", "w[3]", "wave[0].phase") belongs to one of `initialized`
// (by the name before its first '[' or '.').
bool keepsInitialValue(const std::set<std::string>& initialized, const std::string& name);

}  // namespace rmfx
