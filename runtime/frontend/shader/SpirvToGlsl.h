#pragma once
// The SPIRV-Cross half of the HLSL translation: reads the SPIR-V that glslang made of one HLSL
// stage through SPIRV-Cross's reflection, names and decorates its inputs, outputs, uniform blocks
// and samplers the way rmfx binds them, and compiles it to GLSL 4.50. What the reflection found
// comes back with the code, so nothing downstream parses the generated GLSL.

#include <string>
#include <vector>

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

// A variable of the generated GLSL, as SPIRV-Cross's reflection describes it.
struct ReflectedVariable {
    std::string name;         // its GLSL name: "rm_hlsl_TEXCOORD1", "tint"
    std::string type;         // its GLSL type: "vec2", "mat4", "ivec3", or a struct's name
    std::string arraySuffix;  // "[4]", "[2][3]"; empty when not an array
    std::string semantic;     // stage inputs: "TEXCOORD1", "COLOR0" (normalised); else empty
};

// The uniform block glslang makes of the HLSL globals ($Global) or of one cbuffer. In the code it
// is declared `struct <typeName> { … }; uniform <typeName> <instanceName>;` (SPIRV-Cross's plain
// uniform mode) and read as `<instanceName>.member`.
struct ReflectedBlock {
    std::string typeName;      // rm_hlsl_BlockType<k>
    std::string instanceName;  // rm_hlsl_Block<k>
    std::vector<ReflectedVariable> members;
};

struct SpirvGlsl {
    std::string code;
    std::vector<ReflectedBlock> blocks;
    std::vector<ReflectedVariable> inputs;  // the stage inputs that have a semantic, in declaration order
};

// `stage` decides the interface names (see HlslTranslator.h). Fails with SPIRV-Cross's message.
Result<SpirvGlsl> spirvToGlsl(const std::vector<unsigned>& spirv, ShaderStage stage);

}  // namespace rmfx
