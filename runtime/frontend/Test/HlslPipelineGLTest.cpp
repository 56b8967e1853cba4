// Direct3D 9's pipeline around HLSL shaders, rendered: what fixed-function processing gives a pixel
// shader without a vertex shader, table fog and the alpha test after the pixel shader, varyings
// matched as registers were, and Direct3D's clip-space depth.

#include <cmath>

#include <gtest/gtest.h>

#include "HlslGLTestSupport.h"

namespace rmfx::test {
namespace {

using namespace hlsl_gl;

class HlslPipelineGLTest : public GlTest {};

// A pass with a pixel shader only: Direct3D's fixed-function vertex processing gives it the
// mesh's texture coordinates (TEXCOORDn, as (u, v, 0, 1)) and white (COLORn); rmfx's built-in
// vertex shader hands it the same. On the full-screen triangle (u, v) is the pixel's position.
TEST_F(HlslPipelineGLTest, PixelShaderWithoutAVertexShaderReadsWhatFixedFunctionGives) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <shader stage="fragment"><![CDATA[
float4 main(float2 uv : TEXCOORD0, float4 far : TEXCOORD3, float3 colour : COLOR0) : COLOR {
    return float4(uv.x, uv.y + far.w, far.z + colour.g * 0.5, colour.r);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const double u = (x + 0.5) / 4, v = (y + 0.5) / 4;
            expectNear(pixel(out, x, y), {u, v + 1.0, 0.5, 1.0}, 1e-6, "pixel " + std::to_string(x) + "," + std::to_string(y));
        }
}

// Direct3D 9's table fog after a ps_2_0 shader: the colour blends toward the fog colour by the
// pixel's eye-space depth, here the clip w the vertex shader writes (4): linear from 1 to 7 gives
// f = (7 − 4) / 6 = 0.5, exp with density 0.25 exp(−1), exp2 with density 0.25 exp(−1). A ps_3_0
// shader is not fogged, as in Direct3D.
TEST_F(HlslPipelineGLTest, TableFogBlendsTowardTheFogColourByEyeDepth) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <float name="depth" value="0.5"/>
  <float name="w" value="4"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    )" + vertexShaderXml(passThroughVertexShader) +
                            R"(    <shader stage="fragment"><![CDATA[
float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(0.2, 0.4, 0.6, 0.8); }
]]></shader>
  </pass>
</workspace>)";
    const glm::dvec3 colour(0.2, 0.4, 0.6), fog(1.0, 0.5, 0.0);
    struct Case {
        FogMode mode;
        float start, end, density;
        const char* profile;
        double factor;
    };
    for (const Case& c : {Case{FogMode::Linear, 1.0f, 7.0f, 1.0f, "ps_2_0", 0.5}, Case{FogMode::Exp, 0.0f, 1.0f, 0.25f, "ps_2_0", std::exp(-1.0)},
                          Case{FogMode::Exp2, 0.0f, 1.0f, 0.25f, "ps_1_4", std::exp(-1.0)},
                          Case{FogMode::Linear, 1.0f, 7.0f, 1.0f, "ps_3_0", 1.0}}) {
        SCOPED_TRACE(std::string(c.profile) + " mode " + std::to_string(int(c.mode)));
        std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
        ASSERT_TRUE(ws);
        Pass& pass = ws->passes[0];
        pass.fog.enabled = true;
        pass.fog.mode = c.mode;
        pass.fog.start = c.start;
        pass.fog.end = c.end;
        pass.fog.density = c.density;
        pass.fog.color = glm::vec3(fog);
        for (ShaderSource& s : pass.shaders)
            if (s.stage == ShaderStage::Fragment) s.profile = c.profile;
        GlRun run = runWorkspace(std::move(ws), RunSettings());
        ASSERT_TRUE(run.exec);
        RefImage out = readRef(run, "out");
        const glm::dvec3 want = c.factor * colour + (1.0 - c.factor) * fog;
        expectNear(pixel(out, 1, 1), glm::dvec4(want, 0.8), 1e-5, "fogged colour");
    }
}

// Direct3D 9's alpha test after the pixel shader: alpha = u (0.125, 0.375, 0.625, 0.875 across
// the four pixel columns) against ALPHAREF 128 (128/255): a failing pixel is discarded and keeps
// the clear colour.
TEST_F(HlslPipelineGLTest, AlphaTestDiscardsThePixelsWhoseAlphaFails) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x1">
  <target name="out" format="rgba32f" size="4x1"/>
  <pass name="hlsl" target="out">
    <clear color="0 0 1 1"/>
    <shader stage="fragment"><![CDATA[
float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(1, 0, 0, uv.x); }
]]></shader>
  </pass>
</workspace>)";
    const double ref = 128.0 / 255.0;
    for (const auto& [func, name] : {std::pair{CompareFunc::Greater, "greater"}, std::pair{CompareFunc::LessEqual, "less-equal"},
                                     std::pair{CompareFunc::Never, "never"}, std::pair{CompareFunc::Always, "always"}}) {
        SCOPED_TRACE(name);
        std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
        ASSERT_TRUE(ws);
        ws->passes[0].alphaTest = {true, func, static_cast<float>(ref)};
        GlRun run = runWorkspace(std::move(ws), RunSettings());
        ASSERT_TRUE(run.exec);
        RefImage out = readRef(run, "out");
        ASSERT_EQ(out.width, 4);
        for (int x = 0; x < 4; ++x) {
            const double alpha = (x + 0.5) / 4.0;
            const bool passes = func == CompareFunc::Greater ? alpha > ref : func == CompareFunc::LessEqual ? alpha <= ref
                                                                          : func == CompareFunc::Always;
            expectNear(pixel(out, x, 0), passes ? glm::dvec4(1, 0, 0, alpha) : glm::dvec4(0, 0, 1, 1), 1e-6,
                       "pixel " + std::to_string(x));
        }
    }
}

// RenderMonkey's template pixel shader takes `float4 inDiffuse : COLOR0` that its vertex shader
// never writes; Direct3D 9 ran it, GL would not link it. The missing inputs get defined values.
TEST_F(HlslPipelineGLTest, PixelShaderInputsTheVertexShaderDoesNotWriteGetDefinedValuesAndAWarning) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <float name="depth" value="0.5"/>
  <float name="w" value="1"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    )" + vertexShaderXml(passThroughVertexShader) +
                            R"(    <shader stage="fragment"><![CDATA[
float4 main(float4 inDiffuse : COLOR0, float2 uv : TEXCOORD0, float3 extra : TEXCOORD3) : COLOR {
    return inDiffuse * 0.5 + float4(extra, 0.25 * uv.x);
}
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings,
              test::lines({"./hlsl-test.xml:17: warning: <pass name=\"hlsl\">: the pixel shader takes COLOR0, TEXCOORD3 as "
                           "input, which the vertex shader does not write; Direct3D 9 ran it anyway, so rmfx supplies them "
                           "(COLORn opaque white, others (0, 0, 0, 1))"}));
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    // COLOR0 white, TEXCOORD3 (0, 0, 0); uv.x the pixel's texture coordinate (x + 0.5) / 4.
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 1), {0.5, 0.5, 0.5, 0.5 + 0.25 * (x + 0.5) / 4.0}, 1e-6, "pixel " + std::to_string(x));
}

// The stages declare a varying with different sizes (a float written, a float4 read; a float4
// written, a float2 read): Direct3D 9 matched registers, and so does rmfx.
TEST_F(HlslPipelineGLTest, VaryingsOfDifferentSizesMatchAsRegistersDid) {
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    )" + vertexShaderXml(R"(
struct VS_OUTPUT { float4 Pos : POSITION; float Depth : TEXCOORD2; float4 Wide : TEXCOORD3; };
VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {
    VS_OUTPUT o;
    o.Pos = float4(Pos.xy, 0.5, 1);
    o.Depth = 0.75;
    o.Wide = float4(Tex, 0.25, 0.5);
    return o;
}
)") + R"(    <shader stage="fragment"><![CDATA[
float4 main(float4 depth : TEXCOORD2, float2 wide : TEXCOORD3) : COLOR {
    return depth + float4(wide, 0, 0) * 0;
}
]]></shader>
  </pass>
  <target name="out2" format="rgba32f" size="4x4"/>
  <pass name="hlsl2" target="out2">
    )" + vertexShaderXml(R"(
struct VS_OUTPUT { float4 Pos : POSITION; float4 Wide : TEXCOORD3; };
VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {
    VS_OUTPUT o;
    o.Pos = float4(Pos.xy, 0.5, 1);
    o.Wide = float4(Tex, 0.25, 0.5);
    return o;
}
)") + R"(    <shader stage="fragment"><![CDATA[
float4 main(float2 wide : TEXCOORD3) : COLOR { return float4(wide, 1, 1); }
]]></shader>
  </pass>
</workspace>)";
    std::unique_ptr<Workspace> ws = hlslWorkspace(xml);
    ASSERT_TRUE(ws);
    const std::string warnings = formatAll(validateWorkspace(*ws).diagnostics());
    EXPECT_EQ(warnings,
              test::lines({"./hlsl-test.xml:14: warning: <pass name=\"hlsl\">: the stages declare TEXCOORD2 (float → vec4), "
                           "TEXCOORD3 (vec4 → vec2) with different sizes; Direct3D 9 matched them by register, so rmfx "
                           "passes the value on, cut to the size read or filled with 0 (w 1)",
                           "./hlsl-test.xml:31: warning: <pass name=\"hlsl2\">: the stages declare TEXCOORD3 (vec4 → vec2) "
                           "with different sizes; Direct3D 9 matched them by register, so rmfx passes the value on, cut to "
                           "the size read or filled with 0 (w 1)"}));
    GlRun run = runWorkspace(std::move(ws), {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    RefImage out = readRef(run, "out"), out2 = readRef(run, "out2");
    ASSERT_EQ(out.width, 4);
    ASSERT_EQ(out2.width, 4);
    for (int x = 0; x < 4; ++x) {
        expectNear(pixel(out, x, 1), {0.75, 0.0, 0.0, 1.0}, 1e-6, "float → float4, pixel " + std::to_string(x));
        expectNear(pixel(out2, x, 1), {(x + 0.5) / 4.0, (1 + 0.5) / 4.0, 1.0, 1.0}, 1e-6, "float4 → float2, pixel " + std::to_string(x));
    }
}

// An input fixed-function processing does not give is an error naming the semantic.
TEST_F(HlslPipelineGLTest, PixelShaderWithoutAVertexShaderReadingANormalIsAnError) {
    Result<Workspace> parsed = parseWorkspaceText(R"(<workspace version="1" name="hlsl" size="4x4">
  <pass name="hlsl">
    <shader stage="fragment" dialect="hlsl"><![CDATA[
float4 main(float3 n : NORMAL) : COLOR { return float4(n, 1); }
]]></shader>
  </pass>
</workspace>)",
                                                "hlsl-test.xml", ".");
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_EQ(all,
              test::lines({"hlsl-test.xml:3: error: <pass name=\"hlsl\">: the HLSL pixel shader reads NORMAL0, which a pass "
                           "without a vertex shader (Direct3D's fixed-function vertex processing) does not provide: give the "
                           "pass a vertex shader"}));
}

// Direct3D keeps z/w in [0, 1] and writes it to the depth buffer as is; rmfx must give the same
// window depth (gl_FragCoord.z, SV_Position.z in the pixel shader), also when w is not 1.
TEST_F(HlslPipelineGLTest, ClipSpaceDepthFollowsDirect3D) {
    for (double w : {1.0, 2.0}) {
        const std::string xml = R"(<workspace version="1" name="hlsl" size="2x2">
  <float name="depth" value="0.25"/>
  <float name="w" value=")" + glslFloat(w) + R"("/>
  <target name="out" format="rgba32f" size="2x2"/>
  <pass name="hlsl" target="out">
    )" + vertexShaderXml(passThroughVertexShader) +
                                R"(    <shader stage="fragment"><![CDATA[
float4 main(float4 position : SV_Position) : COLOR { return float4(position.z, 0, 0, 1); }
]]></shader>
  </pass>
</workspace>)";
        RefImage out = renderOut(xml);
        ASSERT_EQ(out.width, 2);
        // Direct3D: window depth = z/w = 0.25 (OpenGL without the mapping: (0.25 + 1) / 2 = 0.625).
        EXPECT_NEAR(pixel(out, 1, 1).x, 0.25, 1e-6) << "w = " << w;
    }
}

}  // namespace
}  // namespace rmfx::test
