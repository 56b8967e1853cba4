#pragma once
// Direct3D 9 shader assembly (a parsed d3dasm::Program) to Direct3D 9 HLSL, which rmfx's HLSL path
// (HlslTranslator) then compiles like any RmHLSLShader: one function, `rm_asm_main`, whose
// parameters carry the registers' semantics (v# by dcl_* or the stream map, oPos POSITION,
// oD# COLOR#, oT# TEXCOORD#, oC# COLOR#, t# TEXCOORD#), constants read from HLSL globals named
// after the variables RenderMonkey put in the registers, samplers declared under the names bound to
// their stages.
//
// Lines are kept: the statements of the code's line N are on line N of the HLSL (declarations
// go on line 1, the returns on the last), so glslang's errors point at the assembly's line.
//
// Constant registers, as RenderMonkey filled them (docs/rendermonkey.md, "Assembly shaders"):
// a float variable is (v, 0, 0, 0), a vector its four components, and a 4×4 matrix takes four
// registers, register base+i holding row i of the matrix as RenderMonkey stored it (VALUE_4i …
// VALUE_4i+3), so that `m4x4 oPos, v0, c0` computes M·v, as RenderMonkey's HLSL twins do with
// `mul(view_proj_matrix, Pos)`. rmfx's stored matrices put VALUE_0…3 in the first column, which
// is the HLSL row 0; its semantic matrices (OpenGL's column-vector convention, as RenderMonkey's)
// reach HLSL shaders transposed (gl/GlPassBindings), so that HLSL row i is their row i too: every
// matrix is read the same way.

#include <array>
#include <string>
#include <vector>

#include "core/Value.h"
#include "frontend/shader/D3DAsmProgram.h"

namespace rmfx::d3dasm {

struct ConstantBinding {
    std::string name;  // the variable, declared as an HLSL global of its type
    int firstRegister = 0;
    ValueType type = ValueType::Float;
    int line = 0;                 // of the code, for messages; 0: the first
};

enum class SamplerKind { Unknown, Texture2D, Cube, Volume };

struct SamplerBinding {
    std::string name;  // the sampler uniform: the RmTextureObject / RmSampler name
    int stage = 0;
    SamplerKind kind = SamplerKind::Unknown;  // from the bound texture; dcl_* wins
    // The stage's D3DTSS_BUMPENVMAT00, 01, 10, 11, BUMPENVLSCALE and BUMPENVLOFFSET, which texbem,
    // texbeml and bem read (Direct3D's defaults: 0).
    std::array<float, 4> bumpMatrix{};
    float bumpScale = 0.0f, bumpOffset = 0.0f;
};

// vs_1_1 without dcl_*: v# is the stream channel with REGISTER="#".
struct InputRegister {
    int index = 0;
    std::string semantic;  // "POSITION0", "TEXCOORD1"…
};

struct HlslFromAsm {
    std::string hlsl;
    std::string entryPoint = "rm_asm_main";
    std::string profile;  // "vs_3_0" / "ps_3_0": what the generated HLSL needs
    std::vector<Message> messages;
    bool ok() const;
};

HlslFromAsm translateAssembly(const Program& program, const std::vector<ConstantBinding>& constants,
                              const std::vector<SamplerBinding>& samplers, const std::vector<InputRegister>& streams);

}  // namespace rmfx::d3dasm
