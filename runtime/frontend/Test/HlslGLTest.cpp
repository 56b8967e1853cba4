// Direct3D 9 HLSL vertex/pixel shader pairs rendered through the translator (passes named hlsl*
// are HLSL), against values worked out on the CPU: constants, a texture read with tex2D, the
// matrix convention of runtime/HlslTranslator.h (mul(v, M) is rmfx's M * v), and Direct3D's
// clip-space depth.

#include <cmath>
#include <gtest/gtest.h>
#include <glm/mat4x4.hpp>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/Validation.h"

namespace rmfx::test {
namespace {

class HlslGLTest : public GlTest {};

// Parses `xml`, marks the shaders of passes named hlsl* as HLSL (vs_2_0 / ps_2_0, entry "main")
// and validates it, as an imported Direct3D effect would be.
std::unique_ptr<Workspace> hlslWorkspace(const std::string& xml, const std::filesystem::path& folder = ".") {
    Result<Workspace> parsed = parseWorkspaceText(xml, folder / "hlsl-test.xml", folder);
    if (!parsed.ok()) {
        ADD_FAILURE() << formatAll(parsed.diagnostics());
        return nullptr;
    }
    for (Pass& pass : parsed->passes) {
        if (pass.name.rfind("hlsl", 0) != 0) continue;
        for (ShaderSource& s : pass.shaders) {
            s.dialect = ShaderDialect::Hlsl;
            s.entryPoint = "main";
            s.profile = s.stage == ShaderStage::Vertex ? "vs_2_0" : "ps_2_0";
        }
    }
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    if (hasErrors(d)) {
        ADD_FAILURE() << formatAll(d);
        return nullptr;
    }
    return std::make_unique<Workspace>(std::move(*parsed));
}

// Passes the mesh's position and first texture coordinates on, with a chosen clip-space z and w.
const char* passThroughVertexShader = R"(
float depth;
float w;
struct VS_OUTPUT { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };
VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {
    VS_OUTPUT o;
    o.Pos = float4(Pos.xy * w, depth * w, w);
    o.Tex = Tex;
    return o;
}
)";

std::string vertexShaderXml(const std::string& code) {
    return R"(<shader stage="vertex"><![CDATA[)" + code + "]]></shader>\n";
}

glm::dvec4 pixel(const RefImage& image, int x, int y) { return image.at(x, y); }

// Renders one frame of hlslWorkspace(xml) and reads target "out" back; an empty image (and a test
// failure) when it does not run.
RefImage renderOut(const std::string& xml, const std::filesystem::path& folder = ".") {
    GlRun run = runWorkspace(hlslWorkspace(xml, folder), RunSettings());
    if (!run.exec) return {};
    return readRef(run, "out");
}

void expectNear(glm::dvec4 got, glm::dvec4 want, double tolerance, const std::string& what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << " channel " << c;
}

}  // namespace

// Four pixels: a constant, mul(v, M), mul(M, v) and the interpolated texture coordinates.
TEST_F(HlslGLTest, ConstantsMatricesAndTexCoordsReachThePixelShader) {
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
class HlslMatrixOrderGLTest : public HlslGLTest, public testing::WithParamInterface<const char*> {};

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

// A 4x4 float image read with tex2D at the texel centres comes back texel for texel, the same
// way up as a GLSL texture() read of it (row 0 at the bottom).
TEST_F(HlslGLTest, Tex2DReadsTheTextureBoundUnderTheHlslSamplerName) {
    ScratchDir dir;
    RefImage image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) image.at(x, y) = {0.25 * x + 0.0625 * y, 10.0 + y, -x - 0.5, 1.0 / (1 + x + y)};
    writeFloatExr(dir / "image.exr", image);
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <texture name="Image" file="image.exr"/>
  <float name="depth" value="0.5"/>
  <float name="w" value="1"/>
  <float name="gain" value="2"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="baseMap" texture="Image" filter="nearest"/>
    )" + vertexShaderXml(passThroughVertexShader) +
                            R"(    <shader stage="fragment"><![CDATA[
sampler2D baseMap;
float gain;
float4 main(float2 uv : TEXCOORD0) : COLOR { return tex2D(baseMap, uv) * gain; }
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            expectNear(pixel(out, x, y), 2.0 * image.at(x, y), 1e-6, "texel " + std::to_string(x) + "," + std::to_string(y));
}

// Direct3D 9's untyped `sampler` read with texCUBE is a cube map (glslang alone makes it 2D and
// the pass fails): each axis direction reads its own face.
TEST_F(HlslGLTest, AnUntypedSamplerReadWithTexCubeSamplesTheCubeMap) {
    ScratchDir dir;
    const char* sides[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int face = 0; face < 6; ++face) {
        RefImage image(2, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) image.at(x, y) = {0.125 * (face + 1), 1.0, 0.0, 1.0};
        writeFloatExr(dir / (std::string(sides[face]) + ".exr"), image);
    }
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <cubemap name="Sky">
    <face side="+x" file="px.exr"/> <face side="-x" file="nx.exr"/> <face side="+y" file="py.exr"/>
    <face side="-y" file="ny.exr"/> <face side="+z" file="pz.exr"/> <face side="-z" file="nz.exr"/>
  </cubemap>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="Sky" texture="Sky" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
sampler Sky : register(s0);
float4 main(float2 uv : TEXCOORD0) : COLOR {
    // Column x looks along +x, -y, +z, -z.
    float3 directions[4] = { float3(1, 0.1, 0.2), float3(0.1, -1, 0.2), float3(0.2, 0.1, 1), float3(0.1, 0.2, -1) };
    return texCUBE(Sky, directions[int(uv.x * 4)]);
}
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    const int faceOfColumn[4] = {0, 3, 4, 5};  // +x, -y, +z, -z in OpenGL's face order
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 1), {0.125 * (faceOfColumn[x] + 1), 1.0, 0.0, 1.0}, 1e-6, "column " + std::to_string(x));
}

// tex1D on an untyped sampler bound to an image one texel high (Direct3D 9 has no 1D textures):
// the texel under u.
TEST_F(HlslGLTest, Tex1DOnAnUntypedSamplerReadsAnImageOneTexelHigh) {
    ScratchDir dir;
    RefImage ramp(4, 1);
    for (int x = 0; x < 4; ++x) ramp.at(x, 0) = {0.125 * (x + 1), 2.0 - x, 0.5, 1.0};
    writeFloatExr(dir / "ramp.exr", ramp);
    const std::string xml = R"(<workspace version="1" name="hlsl" size="4x4">
  <texture name="Ramp" file="ramp.exr" mipmaps="false"/>
  <target name="out" format="rgba32f" size="4x4"/>
  <pass name="hlsl" target="out">
    <sampler name="Rainbow" texture="Ramp" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
sampler Rainbow : register(s0);
float4 main(float2 uv : TEXCOORD0) : COLOR { return tex1D(Rainbow, uv.x); }
]]></shader>
  </pass>
</workspace>)";
    RefImage out = renderOut(xml, dir.path());
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 2), ramp.at(x, 0), 1e-6, "column " + std::to_string(x));
}

// A pass with a pixel shader only: Direct3D's fixed-function vertex processing gives it the
// mesh's texture coordinates (TEXCOORDn, as (u, v, 0, 1)) and white (COLORn); rmfx's built-in
// vertex shader hands it the same. On the full-screen triangle (u, v) is the pixel's position.
TEST_F(HlslGLTest, PixelShaderWithoutAVertexShaderReadsWhatFixedFunctionGives) {
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

// A constant nothing in the effect sets ran as zero in Direct3D: a warning, and zero here; one set
// by a variable beside it still gets its value. (In a GLSL pass the same is an error.)
TEST_F(HlslGLTest, AConstantNoVariableFeedsIsZeroWithAWarning) {
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
    EXPECT_NE(warnings.find("warning: <pass name=\"hlsl\">: uniform 'Forgotten' is declared vec4"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("Direct3D ran with its constant register unset, so it is fed zero"), std::string::npos)
        << warnings;
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    for (int x = 0; x < 4; ++x) expectNear(pixel(out, x, 1), {0.25, 0.5, 0.75, 1.0}, 1e-6, "pixel " + std::to_string(x));
}

// fxc's brace elision: an array of float2 and one of float2x2 initialised by flat lists of scalars
// (as RenderMonkey's gausBlur samples), a trailing comma and a comment with commas included.
TEST_F(HlslGLTest, FlatScalarListsInitialiseArraysOfVectorsAndMatricesAsFxcDid) {
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
TEST_F(HlslGLTest, AStructArrayKeepsItsInitialValue) {
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
TEST_F(HlslGLTest, APs1xPixelShaderReadsItsConstantsWithinMinusOneToOne) {
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
TEST_F(HlslGLTest, AConstructorAssignedToSplitsTheValueAmongItsNamesAsFxcDid) {
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
TEST_F(HlslGLTest, AVariableFeedsAConstantAsItSetDirect3DsRegisters) {
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
TEST_F(HlslGLTest, ArrayAndExpressionDefaultsOfConstantsHoldAsFxcFoldedThem) {
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
TEST_F(HlslGLTest, AMatrixDefaultListedRowByRowHoldsAsInDirect3D) {
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

// Direct3D 9's table fog after a ps_2_0 shader: the colour blends toward the fog colour by the
// pixel's eye-space depth, here the clip w the vertex shader writes (4): linear from 1 to 7 gives
// f = (7 − 4) / 6 = 0.5, exp with density 0.25 exp(−1), exp2 with density 0.25 exp(−1). A ps_3_0
// shader is not fogged, as in Direct3D.
TEST_F(HlslGLTest, TableFogBlendsTowardTheFogColourByEyeDepth) {
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
TEST_F(HlslGLTest, AlphaTestDiscardsThePixelsWhoseAlphaFails) {
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

// Swizzles of scalars replicate them, as fxc's did: a variable, a component, a call's result, a
// parenthesised expression and a literal.
TEST_F(HlslGLTest, SwizzlesOfScalarsReplicateThem) {
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
TEST_F(HlslGLTest, AssignmentsToGlobalsWriteACopyAsFxcDid) {
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
    EXPECT_NE(warnings.find("hlsl-test.xml:8: warning: <pass name=\"hlsl\">: the shader assigns to HLSL global 'Gain'"),
              std::string::npos) << warnings;
    EXPECT_NE(warnings.find("hlsl-test.xml:9: warning: <pass name=\"hlsl\">: the shader assigns to HLSL global 'Tint'"),
              std::string::npos) << warnings;
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

// RenderMonkey's template pixel shader takes `float4 inDiffuse : COLOR0` that its vertex shader
// never writes; Direct3D 9 ran it, GL would not link it. The missing inputs get defined values.
TEST_F(HlslGLTest, PixelShaderInputsTheVertexShaderDoesNotWriteGetDefinedValuesAndAWarning) {
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
    EXPECT_NE(warnings.find("warning: <pass name=\"hlsl\">: the pixel shader takes COLOR0, TEXCOORD3 as input, which the vertex "
                            "shader does not write; Direct3D 9 ran it anyway, so rmfx supplies them"),
              std::string::npos) << warnings;
    RefImage out = renderOut(xml);
    ASSERT_EQ(out.width, 4);
    // COLOR0 white, TEXCOORD3 (0, 0, 0); uv.x the pixel's texture coordinate (x + 0.5) / 4.
    for (int x = 0; x < 4; ++x)
        expectNear(pixel(out, x, 1), {0.5, 0.5, 0.5, 0.5 + 0.25 * (x + 0.5) / 4.0}, 1e-6, "pixel " + std::to_string(x));
}

// The stages declare a varying with different sizes (a float written, a float4 read; a float4
// written, a float2 read): Direct3D 9 matched registers, and so does rmfx.
TEST_F(HlslGLTest, VaryingsOfDifferentSizesMatchAsRegistersDid) {
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
    EXPECT_NE(warnings.find("<pass name=\"hlsl\">: the stages declare TEXCOORD2 (float → vec4), TEXCOORD3 (vec4 → vec2) "
                            "with different sizes"),
              std::string::npos) << warnings;
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
TEST_F(HlslGLTest, PixelShaderWithoutAVertexShaderReadingANormalIsAnError) {
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
    EXPECT_NE(all.find("hlsl-test.xml:3: error: <pass name=\"hlsl\">: the HLSL pixel shader reads NORMAL0, which a pass "
                       "without a vertex shader"),
              std::string::npos)
        << all;
}

// Direct3D keeps z/w in [0, 1] and writes it to the depth buffer as is; rmfx must give the same
// window depth (gl_FragCoord.z, SV_Position.z in the pixel shader), also when w is not 1.
TEST_F(HlslGLTest, ClipSpaceDepthFollowsDirect3D) {
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

}  // namespace rmfx::test
