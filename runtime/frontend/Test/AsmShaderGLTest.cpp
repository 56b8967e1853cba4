// Direct3D effects whose passes are assembly shaders (RmShader), written here as .rfx files,
// imported, translated to HLSL and rendered headless. Each pixel is checked against the same
// maths evaluated here in double, from the values in the file: a vs_1_1 + ps_1_1 pass (stream
// registers without dcl_*, a non-symmetric matrix through m4x4, ps_1_1's clamping and modifiers)
// and a vs_2_0 + ps_2_0 pass (m4x4 on the position, texld from a texture the test writes).

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

constexpr int kSize = 16;

using Vec4 = std::array<double, 4>;

std::filesystem::path fixtureDir() {
    std::filesystem::path dir = binaryDir() / "asm-shader-gl-test";
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(sourceDir() / "tests" / "rfx" / "quad.obj", dir / "quad.obj",
                               std::filesystem::copy_options::overwrite_existing);
    return dir;
}

std::unique_ptr<Workspace> loadFixture(const std::string& name, const std::string& text) {
    const std::filesystem::path file = fixtureDir() / name;
    std::ofstream(file) << text;
    Result<Workspace> loaded = loadWorkspace(file);
    if (!loaded.ok()) {
        ADD_FAILURE() << formatAll(loaded.diagnostics());
        return nullptr;
    }
    return std::make_unique<Workspace>(std::move(*loaded));
}

std::string effect(const std::string& inside) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<RENDER_MONKEY>\n"
           " <RmEffectWorkspace NAME=\"Asm\" API=\"\" ACTIVE_EFFECT=\"Asm.Effect\" VALIDATION_STRING=\"\" XML_VERSION=\"RenderMonkey 1.71\">\n"
           "  <RmDirectXEffect NAME=\"Effect\" API=\"D3D\" ACTIVE_CAMERA=\"\">\n" +
           inside +
           "  </RmDirectXEffect>\n </RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

// A matrix variable as RenderMonkey writes one: VALUE_0 … VALUE_15 row by row.
std::string matrixVariable(const std::string& name, const std::array<std::array<double, 4>, 4>& m) {
    std::string s = "<RmMatrixVariable NAME=\"" + name + "\" API=\"\" ARTIST_EDITABLE=\"FALSE\" VARIABLE_SEMANTIC=\"\"";
    for (int i = 0; i < 16; ++i) s += " VALUE_" + std::to_string(i) + "=\"" + std::to_string(m[i / 4][i % 4]) + "\"";
    return s + "/>\n";
}

const char* kQuadAndStreams =
    "   <RmModelData NAME=\"Quad\" API=\"\" FILE_NAME=\"quad.obj\" ORIENTATION=\"0\"/>\n"
    "   <RmStreamMap NAME=\"Streams\" API=\"\"><RmStream NAME=\"Stream\" API=\"\" STRIDE=\"20\">\n"
    "     <RmStreamChannel NAME=\"Position\" API=\"\" DATA_SIZE=\"12\" DATA_TYPE=\"2\" REGISTER=\"0\" USAGE=\"0\" USAGE_INDEX=\"0\"/>\n"
    "     <RmStreamChannel NAME=\"Texcoord\" API=\"\" DATA_SIZE=\"8\" DATA_TYPE=\"1\" REGISTER=\"1\" USAGE=\"5\" USAGE_INDEX=\"0\"/>\n"
    "   </RmStream></RmStreamMap>\n";

const char* kStates =
    "    <RmModelReference NAME=\"Quad\" API=\"\"/>\n"
    "    <RmRenderStateBlock NAME=\"States\" API=\"D3D\">\n"
    "     <RmState NAME=\"D3DRS_ZENABLE\" API=\"D3D\" STATE=\"7\" VALUE=\"0\" USAGE=\"0\"/>\n"
    "     <RmState NAME=\"D3DRS_CULLMODE\" API=\"D3D\" STATE=\"22\" VALUE=\"1\" USAGE=\"0\"/>\n"
    "    </RmRenderStateBlock>\n"
    "    <RmStreamMapReference NAME=\"Streams\" API=\"\"/>\n";

// The fixture written as `name`, imported and rendered one frame at kSize; its output read back, or
// an empty image (and a failure) when it does not load or run.
Image renderedOutput(const std::string& name, const std::string& text) {
    auto ws = loadFixture(name, text);
    if (!ws) return {};
    GlRun run = runWorkspace(std::move(ws), RunSettings{{kSize, kSize}});
    if (!run.exec) {
        ADD_FAILURE() << name << " does not run";
        return {};
    }
    return readBack(*run.exec, run.ws->outputTargetName());
}

double clampTo(double v, double lo, double hi) { return std::min(hi, std::max(lo, v)); }

class AsmShaderGLTest : public GlTest {};

// vs_1_1 without dcl_* (v0, v1 are the stream channels of REGISTER 0 and 1) and ps_1_1.
TEST_F(AsmShaderGLTest, Vs11AndPs11WithAMatrixConstantAndPs1xModifiers) {
    // Rows as RenderMonkey stores them: m4x4 with c0…c3 computes M · (u, v, 0, 1). Its transpose
    // would give other colours everywhere.
    const std::array<std::array<double, 4>, 4> m{{{0.5, 0.25, 0.0, 0.1},
                                                  {0.1, 0.6, 0.0, 0.2},
                                                  {0.3, -0.2, 0.0, 0.4},
                                                  {0.0, 0.0, 0.0, 1.0}}};
    const Vec4 tint{0.6, 0.5, 0.4, 1.0};
    const std::string vs = R"(
vs.1.1
; positions are already in clip space
mov oPos, v0
m4x4 r0, v1, c0   // the texture coordinates through the matrix
mov oT0, r0
mov oD0, c4
)";
    const std::string ps = R"(
ps.1.1
def c1, 0.25, 0.5, 0.75, 1.0
def c2, 0.3, 0.6, 0.9, 0.5
texcoord t0
mul_x2 r1, t0, c1
add_sat r0.rgb, r1, v0_bx2
+mov r0.a, c2.b
mad r0.rgb, 1-r0, c2_bias, r0
sub r1, r0, c1
mul_d2 r0.r, r1.a, -r1_bias
)";
    std::string text = effect(
        matrixVariable("TexMatrix", m) +
        "   <RmVectorVariable NAME=\"Tint\" API=\"\" ARTIST_EDITABLE=\"TRUE\" VARIABLE_SEMANTIC=\"\" VALUE_0=\"0.6\" "
        "VALUE_1=\"0.5\" VALUE_2=\"0.4\" VALUE_3=\"1.0\" MIN=\"0\" MAX=\"1\" CLAMP=\"FALSE\" NORMALIZE=\"FALSE\"/>\n" +
        kQuadAndStreams + "   <RmPass NAME=\"Asm\" API=\"D3D\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + kStates +
        "    <RmShader NAME=\"Vertex Shader\" API=\"D3D\" PIXEL_SHADER=\"FALSE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + vs +
        "]]></RmShaderCode>\n"
        "     <RmShaderConstant NAME=\"TexMatrix\" API=\"\" REGISTER=\"0\"/>\n"
        "     <RmShaderConstant NAME=\"Tint\" API=\"\" REGISTER=\"4\"/>\n"
        "    </RmShader>\n"
        "    <RmShader NAME=\"Pixel Shader\" API=\"D3D\" PIXEL_SHADER=\"TRUE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + ps +
        "]]></RmShaderCode></RmShader>\n"
        "   </RmPass>\n");
    const Image image = renderedOutput("vs11_ps11.rfx", text);
    ASSERT_EQ(image.width, kSize);
    const Vec4 c1{0.25, 0.5, 0.75, 1.0}, c2{0.3, 0.6, 0.9, 0.5};
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            // quad.obj's (u, v) where Direct3D 9 shades pixel (x, y), y from the bottom: at whole-number
            // window coordinates, x from the left and kSize − 1 − y from the top.
            const Vec4 uv{double(x) / kSize, (y + 1.0) / kSize, 0.0, 1.0};
            Vec4 t0{}, r1{}, r0{};
            for (int i = 0; i < 3; ++i) {
                double d = 0.0;
                for (int k = 0; k < 4; ++k) d += m[i][k] * uv[k];
                t0[i] = clampTo(d, 0.0, 1.0);  // texcoord: saturate(xyz), w = 1
            }
            t0[3] = 1.0;
            // ps_1_1's temporaries hold ±8 (PixelShader1xMaxValue), its constants ±1.
            for (int i = 0; i < 4; ++i) r1[i] = clampTo(2.0 * t0[i] * c1[i], -8.0, 8.0);
            for (int i = 0; i < 3; ++i) r0[i] = clampTo(r1[i] + (2.0 * tint[i] - 1.0), 0.0, 1.0);
            r0[3] = c2[2];
            for (int i = 0; i < 3; ++i) r0[i] = clampTo((1.0 - r0[i]) * (c2[i] - 0.5) + r0[i], -8.0, 8.0);
            for (int i = 0; i < 4; ++i) r1[i] = clampTo(r0[i] - c1[i], -8.0, 8.0);
            r0[0] = clampTo(r1[3] * -(r1[0] - 0.5) * 0.5, -8.0, 8.0);
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(atGl(image, x, y, c) - clampTo(r0[c], 0.0, 1.0)));
        }
    expectWithin("max abs error against the shaders' maths", worst, kUnorm8Conversion + 1e-5);
}

// ps_1_x constant registers hold [-1, 1] in every version: a ps_1_4 shader reads an RmShaderConstant
// of (4, -3, 0.5, 2) as (1, -1, 0.5, 1), though its temporaries reach ±8 (KORZINA's CarPaint2Tone
// feeds its zPos of -5 to lrp so).
TEST_F(AsmShaderGLTest, Ps14ReadsItsConstantsWithinMinusOneToOne) {
    const std::string vs = "vs.1.1\nmov oPos, v0\nmov oT0, v1\n";
    const std::string ps = "ps.1.4\ndef c1, 0.25, -0.5, 1.0, 0.125\nmul r0, c0, c1\n";
    std::string text = effect(
        "   <RmVectorVariable NAME=\"Big\" API=\"\" ARTIST_EDITABLE=\"TRUE\" VARIABLE_SEMANTIC=\"\" VALUE_0=\"4\" "
        "VALUE_1=\"-3\" VALUE_2=\"0.5\" VALUE_3=\"2\" MIN=\"-8\" MAX=\"8\" CLAMP=\"FALSE\" NORMALIZE=\"FALSE\"/>\n" +
        std::string(kQuadAndStreams) + "   <RmPass NAME=\"Asm\" API=\"D3D\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + kStates +
        "    <RmShader NAME=\"Vertex Shader\" API=\"D3D\" PIXEL_SHADER=\"FALSE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + vs +
        "]]></RmShaderCode></RmShader>\n"
        "    <RmShader NAME=\"Pixel Shader\" API=\"D3D\" PIXEL_SHADER=\"TRUE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + ps +
        "]]></RmShaderCode>\n"
        "     <RmShaderConstant NAME=\"Big\" API=\"\" REGISTER=\"0\"/>\n"
        "    </RmShader>\n"
        "   </RmPass>\n");
    const Image image = renderedOutput("ps14_constants.rfx", text);
    ASSERT_EQ(image.width, kSize);
    const Vec4 c0{4.0, -3.0, 0.5, 2.0}, c1{0.25, -0.5, 1.0, 0.125};
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) {
        // r0 = clamp(c0) * c1 within ps_1_4's ±8, then the 8-bit output's [0, 1]. Unclamped, c0 would
        // give (1, 1, 0.5, 0.25).
        const double expected = clampTo(clampTo(c0[c], -1.0, 1.0) * c1[c], 0.0, 1.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) worst = std::max(worst, std::abs(atGl(image, x, y, c) - expected));
    }
    expectWithin("max abs error against (0.25, 0.5, 0.5, 0.125)", worst, kUnorm8Conversion + 1e-5);
}

// vs_2_0 with dcl_* and a position matrix; ps_2_0 sampling a texture the test writes.
TEST_F(AsmShaderGLTest, Vs20AndPs20SampleATextureThroughTexld) {
    // Scales the quad by 2 and moves it by (0.5, -0.5): it still covers the viewport. Read as its
    // transpose the matrix would put 0.5·x − 0.5·y + 1 into w instead.
    const std::array<std::array<double, 4>, 4> m{{{2.0, 0.0, 0.0, 0.5},
                                                  {0.0, 2.0, 0.0, -0.5},
                                                  {0.0, 0.0, 1.0, 0.0},
                                                  {0.0, 0.0, 0.0, 1.0}}};
    const Vec4 weights{0.25, 0.5, 0.125, 0.0};
    const std::filesystem::path dir = fixtureDir();
    Image texture;
    texture.width = kSize, texture.height = kSize, texture.channels = 4;
    texture.pixels.resize(size_t(kSize) * kSize * 4);
    auto texel = [](int i, int j) { return Vec4{i * 16 / 255.0, j * 16 / 255.0, (i + j) * 8 / 255.0, 1.0}; };
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
            for (int c = 0; c < 4; ++c) texture.at(i, kSize - 1 - j, c) = float(texel(i, j)[c]);  // j from the bottom
    ASSERT_TRUE(writeImage(dir / "texels.png", texture));

    const std::string vs = R"(
vs_2_0
dcl_position v0
dcl_texcoord0 v1
m4x4 oPos, v0, c0
mov oT0, v1
)";
    const std::string ps = R"(
ps_2_0
dcl t0.xy
dcl_2d s0
def c0, 0.5, 0.25, 2.0, 1.0
texld r0, t0, s0
mad r1, r0, c0.z, -c0.w
cmp r2, r1, r0, c0.x
dp3 r3.x, r0, c1
mov r2.w, r3.x
mov_sat oC0, r2
)";
    std::string text = effect(
        matrixVariable("Placement", m) +
        "   <RmVectorVariable NAME=\"Weights\" API=\"\" ARTIST_EDITABLE=\"TRUE\" VARIABLE_SEMANTIC=\"\" VALUE_0=\"0.25\" "
        "VALUE_1=\"0.5\" VALUE_2=\"0.125\" VALUE_3=\"0.0\" MIN=\"0\" MAX=\"1\" CLAMP=\"FALSE\" NORMALIZE=\"FALSE\"/>\n"
        "   <Rm2DTextureVariable NAME=\"Texels\" API=\"\" ARTIST_EDITABLE=\"FALSE\" VARIABLE_SEMANTIC=\"\" "
        "FILE_NAME=\"texels.png\" ORIGIN=\"0\"/>\n" +
        kQuadAndStreams + "   <RmPass NAME=\"Asm\" API=\"D3D\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + kStates +
        "    <RmShader NAME=\"Vertex Shader\" API=\"D3D\" PIXEL_SHADER=\"FALSE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + vs +
        "]]></RmShaderCode>\n"
        "     <RmShaderConstant NAME=\"Placement\" API=\"\" REGISTER=\"0\"/>\n"
        "    </RmShader>\n"
        "    <RmShader NAME=\"Pixel Shader\" API=\"D3D\" PIXEL_SHADER=\"TRUE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + ps +
        "]]></RmShaderCode>\n"
        "     <RmShaderConstant NAME=\"Weights\" API=\"\" REGISTER=\"1\"/>\n"
        "    </RmShader>\n"
        "    <RmTextureObject NAME=\"baseMap\" API=\"D3D\" STATE_INDEX=\"0\"><RmTextureReference NAME=\"Texels\" API=\"\"/></RmTextureObject>\n"
        "   </RmPass>\n");
    const Image image = renderedOutput("vs20_ps20.rfx", text);
    ASSERT_EQ(image.width, kSize);
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            // The pixel's clip position back through the matrix to the quad's (u, v). Direct3D 9 shades
            // pixel (x, y) (y from the bottom) at whole-number window coordinates: x from the left,
            // kSize − 1 − y from the top.
            const double cx = 2.0 * x / kSize - 1.0, cy = 2.0 * (y + 1.0) / kSize - 1.0;
            const double qx = (cx - m[0][3]) / m[0][0], qy = (cy - m[1][3]) / m[1][1];
            const double u = (qx + 1.0) / 2.0, v = (qy + 1.0) / 2.0;
            // D3D's default sampler states: point sampling, of row floor(v · kSize) from the image's
            // top (Direct3D's v = 0; quad.obj's v runs up, so the image shows upside down; texel()'s j
            // counts from the bottom). Where a pixel lands on a texel edge (every
            // other column and row here: the quad is scaled by 2), float interpolation may round to
            // either texel, in Direct3D as here: both are allowed.
            const auto texels = [](double t) {
                const double at = t * kSize, nearest = std::round(at);
                return std::abs(at - nearest) < 1e-6 ? std::array<int, 2>{int(nearest) - 1, int(nearest)}
                                                     : std::array<int, 2>{int(std::floor(at)), int(std::floor(at))};
            };
            double best = 1e9;
            for (int i : texels(u))
                for (int k : texels(v)) {
                    const Vec4 tex = texel(std::clamp(i, 0, kSize - 1), kSize - 1 - std::clamp(k, 0, kSize - 1));
                    Vec4 out{};
                    for (int c = 0; c < 4; ++c) out[c] = 2.0 * tex[c] - 1.0 >= 0.0 ? tex[c] : 0.5;
                    out[3] = tex[0] * weights[0] + tex[1] * weights[1] + tex[2] * weights[2];
                    double error = 0.0;
                    for (int c = 0; c < 4; ++c) error = std::max(error, std::abs(atGl(image, x, y, c) - clampTo(out[c], 0.0, 1.0)));
                    best = std::min(best, error);
                }
            worst = std::max(worst, best);
        }
    expectWithin("max abs error against the shaders' maths", worst, kUnorm8Conversion + 1e-5);
}

}  // namespace
}  // namespace rmfx::test
