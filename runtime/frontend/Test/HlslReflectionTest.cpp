// What the HLSL translation learns from SPIRV-Cross's reflection instead of reading its own GLSL:
// a stage's inputs (semantic, GLSL name and type), the members of the blocks glslang makes of the
// globals and cbuffers (declared as plain uniforms of their reflected types), and the varyings
// Direct3D's fixed-function vertex processing hands a pixel shader, made from those inputs.

#include "frontend/shader/HlslTranslator.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::lines;

Result<HlslTranslation> translatePixel(const std::string& code) {
    ShaderInput input;
    input.code = code;
    input.start = {"effect.rfx", 1};
    Diagnostics d;
    PreprocessedShader hlsl = preprocessShader(input, d);
    EXPECT_TRUE(d.empty()) << formatAll(d);
    return translateHlslStage(hlsl, {ShaderStage::Fragment, "main", "ps_3_0"}, {"effect.rfx", 1}, "<RmHLSLShader>");
}

// "SEMANTIC type name" of each input, sorted.
std::vector<std::string> described(const std::vector<ReflectedVariable>& inputs) {
    std::vector<std::string> out;
    for (const ReflectedVariable& v : inputs) out.push_back(v.semantic + " " + v.type + v.arraySuffix + " " + v.name);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(HlslReflection, PixelInputsCarryTheirNormalisedSemanticGlslNameAndType) {
    Result<HlslTranslation> t = translatePixel(lines({
        "float4 main(float2 uv : TEXCOORD1, float4 tint : color0, float fog : TexCoord3) : COLOR {",
        "    return tint * fog + float4(uv, 0, 0);",
        "}",
    }));
    ASSERT_TRUE(t) << t.error();
    EXPECT_EQ(described(t->inputs), (std::vector<std::string>{"COLOR0 vec4 rm_hlsl_COLOR0", "TEXCOORD1 vec2 rm_hlsl_TEXCOORD1",
                                                              "TEXCOORD3 float rm_hlsl_TEXCOORD3"}));
}

TEST(HlslReflection, BlockMembersAreDeclaredAsUniformsOfTheirReflectedTypes) {
    Result<HlslTranslation> t = translatePixel(lines({
        "cbuffer Params { int4 counts; uint mask; bool enabled; float4 ramp[3]; };",
        "float3 axis = float3(0, 0.5, 1);",
        "float4 main(float2 uv : TEXCOORD0) : COLOR {",
        "    float4 c = ramp[counts.x] * (enabled ? 1.0 : 0.0) + float4(axis, 0);",
        "    return c * float(mask & 1u) + float4(uv, 0, 0);",
        "}",
    }));
    ASSERT_TRUE(t) << t.error();
    // HLSL int4 → ivec4, uint → uint, float4[3] → vec4[3]; a bool in a block is a uint in SPIR-V (a
    // bool has no size to lay out). The global float3 (in the other block) keeps its initial value.
    for (const char* declaration : {"uniform ivec4 counts;", "uniform uint mask;", "uniform uint enabled;",
                                    "uniform vec4 ramp[3];", "uniform vec3 axis = vec3(0.0, 0.5, 1.0);"})
        EXPECT_NE(t->glsl.code.find(declaration), std::string::npos) << declaration << "\n" << t->glsl.code;
    EXPECT_EQ(t->glsl.code.find("rm_hlsl_Block"), std::string::npos) << t->glsl.code;
}

TEST(HlslReflection, FixedFunctionVaryingsForTexCoordsAndColours) {
    const std::vector<ReflectedVariable> inputs = {
        {"rm_hlsl_TEXCOORD1", "vec2", "", "TEXCOORD1"},
        {"rm_hlsl_COLOR0", "vec4", "", "COLOR0"},
        {"rm_hlsl_TEXCOORD3", "float", "", "TEXCOORD3"},
    };
    Result<FixedFunctionVaryings> v = hlslFixedFunctionVaryings(inputs);
    ASSERT_TRUE(v) << v.error();
    EXPECT_EQ(v->declarations, "out vec2 rm_hlsl_TEXCOORD1;\nout vec4 rm_hlsl_COLOR0;\nout float rm_hlsl_TEXCOORD3;\n");
    EXPECT_EQ(v->assignments, "    rm_hlsl_TEXCOORD1 = vec4(rm_TexCoordIn, 0.0, 1.0).xy;\n"
                              "    rm_hlsl_COLOR0 = vec4(1.0);\n"
                              "    rm_hlsl_TEXCOORD3 = vec4(rm_TexCoordIn, 0.0, 1.0).x;\n");
}

TEST(HlslReflection, FixedFunctionVaryingsRefuseWhatDirect3DDoesNotHandOn) {
    Result<FixedFunctionVaryings> normal = hlslFixedFunctionVaryings({{"rm_hlsl_NORMAL0", "vec3", "", "NORMAL0"}});
    ASSERT_FALSE(normal);
    EXPECT_NE(normal.error().find("reads NORMAL0, which a pass without a vertex shader"), std::string::npos) << normal.error();
    Result<FixedFunctionVaryings> integer = hlslFixedFunctionVaryings({{"rm_hlsl_TEXCOORD0", "ivec2", "", "TEXCOORD0"}});
    ASSERT_FALSE(integer);
    EXPECT_NE(integer.error().find("reads TEXCOORD0,"), std::string::npos) << integer.error();
}

// The text path read `in vec2 rm_hlsl_TEXCOORD0[2];` as semantic "TEXCOORD0[2]" and reported
// "TEXCOORD0[2]0"; the reflection knows the semantic and that the input is an array.
TEST(HlslReflection, ArrayInputIsRefusedUnderItsSemantic) {
    Result<HlslTranslation> t = translatePixel(lines({
        "float4 main(float2 uv[2] : TEXCOORD0) : COLOR {",
        "    return float4(uv[0] + uv[1], 0, 1);",
        "}",
    }));
    ASSERT_TRUE(t) << t.error();
    ASSERT_EQ(t->inputs.size(), 1u);
    EXPECT_EQ(t->inputs[0].arraySuffix, "[2]");
    Result<FixedFunctionVaryings> v = hlslFixedFunctionVaryings(t->inputs);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().find("reads TEXCOORD0, which"), std::string::npos) << v.error();
}

}  // namespace rmfx
