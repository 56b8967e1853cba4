// Direct3D 9 HLSL constants rendered through the translator, against values worked out on the CPU:
// constants and their defaults as fxc folded them, the matrix convention of HlslTranslator.h
// (mul(v, M) is rmfx's M * v) and the declared order, registers set from variables, swizzles of
// scalars and assignments to globals.

#include <string>

#include <gtest/gtest.h>

#include "HlslGLTestSupport.h"

namespace rmfx::test {
namespace {

using namespace hlsl_gl;

class HlslConstantsGLTest : public GlTest {};

// Four pixels: a constant, mul(v, M), mul(M, v) and the interpolated texture coordinates.
TEST_F(HlslConstantsGLTest, ConstantsMatricesAndTexCoordsReachThePixelShader) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x1">
  <vec4 name="tint" value="0.125 -2.5 3.75 1"/>
  <vec4 name="v" value="1 -2 3 0.5"/>
  <mat4 name="M" value="1 2 3 4  5 6 7 8  9 10 11 12  13 14 15 16.5"/>
  <float name="depth" value="0.25"/>
  <float name="w" value="1"/>
  <target name="out" format="rgba32f" size="4x1"/>
  <pass name="hlsl" target="out">
    )" + vertexShaderXml(passThroughVertexShader) +
                            R"(    <shader stage="fragment"><![CDATA[
float4 tint;
float4 v;
float4x4 M;
float4 main(float2 uv : TEXCOORD0) : COLOR {
    if (uv.x < 0.25) return tint;
    if (uv.x < 0.5) return mul(v, M);
    if (uv.x < 0.75) return mul(M, v);
    return float4(uv, 0, 1);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);

    // rmfx's matrix: the 16 numbers are its columns.
    double values[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16.5};
    auto m = [&](int row, int column) { return values[4 * column + row]; };
    glm::dvec4 v(1, -2, 3, 0.5), mv(0.0), mtv(0.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            mv[r] += m(r, c) * v[c];   // rmfx's M * v
            mtv[r] += m(c, r) * v[c];  // transpose(M) * v
        }
    expectNear(pixel(out, 0, 0), {0.125, -2.5, 3.75, 1}, 0.0, "tint");
    expectNear(pixel(out, 1, 0), mv, 1e-4, "mul(v, M) is rmfx's M * v");
    expectNear(pixel(out, 2, 0), mtv, 1e-4, "mul(M, v) is transpose(M) * v");
    expectNear(pixel(out, 3, 0), {0.875, 0.5, 0, 1}, 1e-6, "TEXCOORD0 at the pixel centre");
}

// An HLSL shader multiplies a semantic matrix the way its matrices="…" says: row-vector (the
// default, D3DX's and RenderMonkey 1.6's mul(v, M)) or column-vector (RenderMonkey 1.5's
// mul(view_proj_matrix, Pos)); either way that product is World·v, the other one is v·World. A
// stored matrix keeps the layout above. World here is the pass's translate and scale.
class HlslMatrixOrderGLTest : public GlTest, public testing::WithParamInterface<const char*> {};

TEST_P(HlslMatrixOrderGLTest, TheProductInTheDeclaredOrderIsWorldTimesV) {
    const std::string order = GetParam();
    const std::string attribute = order.empty() ? "" : " matrices=\"" + order + "\"";
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x1">
  <mat4 name="world" semantic="World"/>
  <target name="out" format="rgba32f" size="4x1"/>
  <pass name="hlsl" target="out">
    <draw mesh="fullscreen" translate="0.5 -0.25 1" scale="2 0.5 1.5"/>
    <shader stage="fragment" dialect="hlsl")" + attribute + R"(><![CDATA[
float4x4 world;
float4 main(float2 uv : TEXCOORD0) : COLOR {
    float4 v = float4(1, -2, 3, 1);
    return uv.x < 0.5 ? mul(world, v) : mul(v, world);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    // World = translate(0.5, -0.25, 1) · scale(2, 0.5, 1.5), in column-vector convention.
    const glm::dvec4 worldTimesV{2.0 * 1 + 0.5, 0.5 * -2 - 0.25, 1.5 * 3 + 1, 1};
    // v · World: each column of World dotted with v; the translation lands in w.
    const glm::dvec4 vTimesWorld{2.0 * 1, 0.5 * -2, 1.5 * 3, 0.5 * 1 - 0.25 * -2 + 1 * 3 + 1};
    const bool columnVector = order == "column-vector";
    expectNear(pixel(out, 0, 0), columnVector ? worldTimesV : vTimesWorld, 1e-5, "mul(world, v)");
    expectNear(pixel(out, 3, 0), columnVector ? vTimesWorld : worldTimesV, 1e-5, "mul(v, world)");
}

INSTANTIATE_TEST_SUITE_P(Orders, HlslMatrixOrderGLTest, testing::Values("", "row-vector", "column-vector"),
                         [](const testing::TestParamInfo<const char*>& info) {
                             const std::string p = info.param;
                             return p.empty() ? std::string("Default") : p == "row-vector" ? std::string("RowVector")
                                                                                            : std::string("ColumnVector");
                         });

// A constant nothing in the effect sets ran as zero in Direct3D: a warning, and zero here; one set
// by a variable beside it still gets its value. (In a GLSL pass the same is an error.)
TEST_F(HlslConstantsGLTest, AConstantNoVariableFeedsIsZeroWithAWarning) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <vec4 name="Tint" value="0.25 0.5 0.75 1"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 Tint;
float4 Forgotten;
float4 main(float2 uv : TEXCOORD0) : COLOR { return Tint + Forgotten * uv.x; }
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings,
              test::lines({"./hlsl-test.xml:5: warning: <pass name=\"hlsl\">: uniform 'Forgotten' is declared vec4, but no "
                           "variable, pass constant or predefined value has that name; Direct3D ran with its constant "
                           "register unset, so it is fed zero"}));
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 1), {0.25, 0.5, 0.75, 1.0}, 1e-6, "pixel " + std::to_string(x));
}

// fxc's brace elision: an array of float2 and one of float2x2 initialised by flat lists of scalars
// (as RenderMonkey's gausBlur samples), a trailing comma and a comment with commas included.
TEST_F(HlslConstantsGLTest, FlatScalarListsInitialiseArraysOfVectorsAndMatricesAsFxcDid) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
static const float2 offsets[3] = {
   0.125, 0.25,   // first, (x, y)
   0.375, 0.5,
   0.625, 0.75,
};
static const float2x2 turns[2] = { 1, 2, 3, 4,  5, 6, 7, 8 };
float4 main(float2 uv : TEXCOORD0) : COLOR {
    float2 sum = offsets[0] + offsets[1] + offsets[2];
    return float4(sum, offsets[2].y, turns[1][0][1] + turns[0][1][0]);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    // turns[1] = float2x2(5, 6, 7, 8): row 0 (5, 6), so [0][1] = 6; turns[0][1][0] = 3.
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 2), {0.125 + 0.375 + 0.625, 0.25 + 0.5 + 0.75, 0.75, 6.0 + 3.0}, 1e-6, "pixel " + std::to_string(x));
}

// A struct array's initial value is the constants' default, as for scalars and vectors
// (ocean_from_composer's `Wave wave[2] = {{1, 1, 0.5, float2(-1, 0)}, …}`, whose phase and
// direction no variable feeds); nothing is warned as fed zero.
TEST_F(HlslConstantsGLTest, AStructArrayKeepsItsInitialValue) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
struct Wave {
  float freq;
  float amp;
  float phase;
  float2 dir;
};
Wave wave[2] = {
   { 1.0, 1.0, 0.5, float2(-1, 0) },
   { 2.0, 0.5, 1.3, float2(-0.7, 0.7) }
};
float4 main(float2 uv : TEXCOORD0) : COLOR {
    return float4(wave[0].phase + wave[1].freq, wave[1].amp, wave[1].dir.y - wave[0].dir.x, wave[1].phase);
}
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings.find("fed zero"), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find("not carried over"), std::string::npos) << warnings;
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 1), {0.5 + 2.0, 0.5, 0.7 + 1.0, 1.3}, 1e-6, "pixel " + std::to_string(x));
}

// A pixel shader compiled for ps_1_x reads its constants clamped to [-1, 1], as Direct3D 9's ps_1_x
// constant registers held them (USE_RenderTarget's Motion Blur: a ps_1_4 light direction of
// (4.2, 1.4, -0.8)); for ps_2_0 they are as set.
TEST_F(HlslConstantsGLTest, APs1xPixelShaderReadsItsConstantsWithinMinusOneToOne) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <vec4 name="k" value="4 -3 0.5 2"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 k;
float4 main(float2 uv : TEXCOORD0) : COLOR { return k * float4(0.25, -0.25, 1.0, 0.125); }
]]></shader>
  </pass>
</workspace>)";
    for (const auto& [profile, expected] : {std::pair{std::string("ps_1_4"), glm::dvec4(0.25, 0.25, 0.5, 0.125)},
                                            std::pair{std::string("ps_2_0"), glm::dvec4(1.0, 0.75, 0.5, 0.25)}}) {
        std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
        ASSERT_TRUE(ws);
        for (ShaderSource& s : ws->passes[0].shaders)
            if (s.stage == ShaderStage::Fragment) s.profile = profile;
        GlRun run = runWorkspace(std::move(ws), RunSettings());
        ASSERT_TRUE(run.exec) << profile;
        const RefImage out = readRef(run, "out");
        for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 1), expected, 1e-6, profile + " pixel " + std::to_string(x));
    }
}

// fxc accepted a constructor as an assignment's target (ATI's Iridescent Butterfly:
// `float4(vNormal, fGloss) = tex2D(…)`): the value's components go to the names in order.
TEST_F(HlslConstantsGLTest, AConstructorAssignedToSplitsTheValueAmongItsNamesAsFxcDid) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 main(float2 uv : TEXCOORD0) : COLOR {
    float3 vNormal, baseColor;
    float  fGloss;
    float4(vNormal, fGloss) = float4(0.125, 0.25, 0.375, 0.5);
    return float4(fGloss, vNormal.zyx);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    expectNear(pixel(out, 1, 2), {0.5, 0.375, 0.25, 0.125}, 0.0, "pixel");
}

// RenderMonkey set a Direct3D constant register from the variable of its name: a float4
// variable into a float2 constant gives .xy (a register is four floats), and an array constant
// `float4 weights[2]` takes the variable in its first register, the second staying zero.
TEST_F(HlslConstantsGLTest, AVariableFeedsAConstantAsItSetDirect3DsRegisters) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <vec4 name="offset" value="0.25 0.5 0.75 1"/>
  <vec3 name="gain" value="2 3 4"/>
  <vec4 name="weights" value="0.125 0.375 0.625 0.875"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <target name="out2" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float2 offset;
float gain;
float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(offset, gain, 0); }
]]></shader>
  </pass>
  <pass name="hlsl_array" target="out2">
    <shader stage="fragment"><![CDATA[
float4 weights[2];
float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(weights[0].yw, weights[1].xw); }
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), RunSettings());
    ASSERT_TRUE(run.exec);
    expectNear(pixel(readRef(run, "out"), 2, 1), {0.25, 0.5, 2.0, 0.0}, 0.0, "offset.xy, gain = gain.x");
    expectNear(pixel(readRef(run, "out2"), 1, 3), {0.375, 0.875, 0.0, 0.0}, 0.0, "weights[0].yw, weights[1] zero");
}

// A constant's default may be an expression and an array (tdm1223's Blur.rfx: a Gaussian kernel
// `float4 gaussFilter[7] = { 0.0, -3.0, 0.0, 1.0/64.0, … }` and `float texScaler = 1.0/2048.0;`):
// fxc folded them, and they hold while no variable feeds the constant.
TEST_F(HlslConstantsGLTest, ArrayAndExpressionDefaultsOfConstantsHoldAsFxcFoldedThem) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 gaussFilter[3] =
{
   0.0, -1.0, 0.0, 1.0/4.0,
   0.0,  0.0, 0.0, 2.0/4.0,
   0.0,  1.0, 0.0, 1.0/4.0
};
float texScaler = 1.0/2048.0;
float4 main(float2 uv : TEXCOORD0) : COLOR {
    return float4(gaussFilter[0].w + 2 * gaussFilter[1].w, gaussFilter[2].y, texScaler * 1024, gaussFilter[0].y);
}
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings.find("gaussFilter"), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find("texScaler"), std::string::npos) << warnings;
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 1), {0.25 + 2 * 0.5, 1.0, 0.5, -1.0}, 1e-6, "pixel " + std::to_string(x));
}

// A matrix constant's default, listed row by row as HLSL does (popekim's EdgeDetection.rfx: Sobel
// kernels `float3x3 Kx = { -1, 0, 1, -2, 0, 2, -1, 0, 1 };`): row 0 is (-1, 0, 1), so
// mul(float3(1, 0, 0), Kx) = (-1, 0, 1), Kx[1][0] = -2 and mul(Kx, float3(0, 0, 1)) is column 2,
// (1, 2, 1).
TEST_F(HlslConstantsGLTest, AMatrixDefaultListedRowByRowHoldsAsInDirect3D) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x1">
  <target name="out" format="rgba32f" size="4x1"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float3x3 Kx = { -1, 0, 1, -2, 0, 2, -1, 0, 1 };
float4 main(float2 uv : TEXCOORD0) : COLOR {
    if (uv.x < 0.5) return float4(mul(float3(1, 0, 0), Kx), Kx[1][0]);
    return float4(mul(Kx, float3(0, 0, 1)), 0);
}
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings.find("Kx"), std::string::npos) << warnings;
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    expectNear(pixel(out, 0, 0), {-1, 0, 1, -2}, 1e-6, "row 0 and Kx[1][0]");
    expectNear(pixel(out, 3, 0), {1, 2, 1, 0}, 1e-6, "column 2");
}

// Swizzles of scalars replicate them, as fxc's did: a variable, a component, a call's result, a
// parenthesised expression and a literal.
TEST_F(HlslConstantsGLTest, SwizzlesOfScalarsReplicateThem) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 main(float2 uv : TEXCOORD0) : COLOR {
    float f = 0.5;
    float2 a = f.xx;
    float3 b = uv.x.xxx;
    float4 c = dot(a, a).xxxx;
    float4 d = (f * 2).rrrr;
    return float4(a.y, b.z, c.w, d.a) + 0.125f.xxxx;
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) {
        const double u = (x + 0.5) / 4.0;
        expectNear(pixel(out, x, 1), glm::dvec4(0.5, u, 0.5, 1.0) + 0.125, 1e-6, "pixel " + std::to_string(x));
    }
}

// fxc let a shader assign to a global constant (a copy private to each run): Gain doubled and
// Tint's x replaced inside the shader, a helper function reading the copies, the constants
// themselves fed by the workspace's variables and unchanged for the next pass.
TEST_F(HlslConstantsGLTest, AssignmentsToGlobalsWriteACopyAsFxcDid) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <float name="Gain" value="0.75"/>
  <vec4 name="Tint" value="0.5 0.25 0.125 1"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <target name="again" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float Gain;
float4 Tint;
float4 scaled(float4 c) { return c * Gain; }
float4 main(float2 uv : TEXCOORD0) : COLOR {
    Gain *= 2;
    Tint.x = 0.25;
    Tint[1] += Gain == 1.5 ? 1 : 0;
    return scaled(Tint);
}
]]></shader>
  </pass>
  <pass name="hlsl_again" target="again">
    <shader stage="fragment"><![CDATA[
float Gain;
float4 Tint;
float4 main(float2 uv : TEXCOORD0) : COLOR { return Tint * Gain; }
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings,
              test::lines({"./hlsl-test.xml:8: warning: <pass name=\"hlsl\">: the shader assigns to HLSL global 'Gain': "
                           "Direct3D 9's compiler gave each run of the shader a writable copy of the constant, and so does rmfx",
                           "./hlsl-test.xml:9: warning: <pass name=\"hlsl\">: the shader assigns to HLSL global 'Tint': "
                           "Direct3D 9's compiler gave each run of the shader a writable copy of the constant, and so does "
                           "rmfx"}));
    GlRun run = runWorkspace(std::move(ws), {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    RefImage out = readRef(run, "out"), again = readRef(run, "again");
    ASSERT_EQ(out.width, 4);
    ASSERT_EQ(again.width, 4);
    const double gain = 0.75 * 2;  // the copy, doubled
    const glm::dvec4 tint{0.25, 0.25 + 1.0, 0.125, 1.0};
    for (int x = 0; x < 4; ++x) {
        expectNear(pixel(out, x, 1), tint * gain, 1e-6, "pixel " + std::to_string(x));
        expectNear(pixel(again, x, 1), glm::dvec4(0.5, 0.25, 0.125, 1.0) * 0.75, 1e-6, "next pass, pixel " + std::to_string(x));
    }
}

}  // namespace
}  // namespace rmfx::test
