// Direct3D 9's texture space, as RenderMonkey's Direct3D effects rely on it: v = 0 is the top row
// of an image and of a render target, window y points down, a pixel is shaded with what lies at
// its whole-number position (D3D9's half pixel) and VPOS is that position. Each test writes a
// Direct3D .rfx reproducing what public post-processing files do (RenderMonkey's stock
// ScreenAlignedQuad.3ds, whose texture coordinates put v = 0 at its top edge; a combine pass that
// builds its texture coordinates from the position, Direct3D's way: 0.5 * (1 - Pos.y)) around a
// picture whose top differs from its bottom and left from right, and compares the output with a
// float64 model of what Direct3D 9 computes, worked out here pixel by pixel.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "reference/CpuImage.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/ModelFiles.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

// Not square, so a transpose shows too.
constexpr int kWidth = 16, kHeight = 12;

// The picture's texel at column i, row r counted from the TOP: every row and column differs.
glm::dvec4 pictureTexel(int i, int r) {
    return glm::dvec4(16 * i + 8, 20 * r + 10, ((i + 2 * r) % 5) * 50, 255) / 255.0;
}

// Images here are held top row first (row index r from the top), so that Direct3D's (u, v)
// samples them with CpuImage's GL_LINEAR arithmetic as they stand: texel centres at (i + 0.5) / size.
RefImage topFirstPicture() {
    RefImage picture(kWidth, kHeight);
    for (int r = 0; r < kHeight; ++r)
        for (int i = 0; i < kWidth; ++i) picture.at(i, r) = pictureTexel(i, r);
    return picture;
}

void writePicture(const std::filesystem::path& file) {
    Image image;
    image.width = kWidth, image.height = kHeight, image.channels = 4;
    image.pixels.resize(size_t(kWidth) * kHeight * 4);
    for (int r = 0; r < kHeight; ++r)
        for (int i = 0; i < kWidth; ++i)
            for (int c = 0; c < 4; ++c) image.at(i, r, c) = float(pictureTexel(i, r)[c]);  // Image rows run top down
    auto written = writeImage(file, image);
    ASSERT_TRUE(written) << (written ? "" : written.error());
}

// RenderMonkey's ScreenAlignedQuad.3ds as the public copies of it are laid out: the square
// [-1, 1]² in the file's xy plane, v = 0 along its top edge (y = 1), u = 0 along its left edge.
// Its two triangles run clockwise on a Direct3D screen (y down), Direct3D's front faces.
void writeScreenAlignedQuad(const std::filesystem::path& file) {
    Mesh quad;
    quad.positions = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
    quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    write3ds(file, quad);
}

// Direct3D 9 shades the pixel at column x, row r (from the top) of a w x h target with what lies
// at window position (x, r): on a quad covering the screen, texture coordinates (x / w, r / h).
glm::dvec2 quadUv(int x, int r, int w, int h) { return glm::dvec2(double(x) / w, double(r) / h); }

const char* kSamplerStates =
    "     <RmState NAME=\"D3DSAMP_ADDRESSU\" API=\"D3D\" STATE=\"1\" VALUE=\"3\" USAGE=\"0\"/>\n"
    "     <RmState NAME=\"D3DSAMP_ADDRESSV\" API=\"D3D\" STATE=\"2\" VALUE=\"3\" USAGE=\"0\"/>\n"
    "     <RmState NAME=\"D3DSAMP_MAGFILTER\" API=\"D3D\" STATE=\"5\" VALUE=\"2\" USAGE=\"0\"/>\n"
    "     <RmState NAME=\"D3DSAMP_MINFILTER\" API=\"D3D\" STATE=\"6\" VALUE=\"2\" USAGE=\"0\"/>\n"
    "     <RmState NAME=\"D3DSAMP_MIPFILTER\" API=\"D3D\" STATE=\"7\" VALUE=\"0\" USAGE=\"0\"/>\n";

std::string textureObject(const std::string& sampler, const std::string& texture) {
    return "    <RmTextureObject NAME=\"" + sampler + "\" API=\"D3D\" STATE_INDEX=\"0\" VERTEX_TEXTURE=\"FALSE\">\n"
           "     <RmTextureReference NAME=\"" + texture + "\" API=\"\"/>\n" + kSamplerStates + "    </RmTextureObject>\n";
}

std::string hlsl(const std::string& name, bool pixel, const std::string& target, const std::string& code,
                 const std::string& bindings = "") {
    return "    <RmHLSLShader NAME=\"" + name + "\" API=\"D3D\" PIXEL_SHADER=\"" + (pixel ? "TRUE" : "FALSE") +
           "\" TARGET=\"" + target + "\" ENTRY_POINT=\"main\" COMPILER_FLAGS=\"\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" +
           code + "]]></RmShaderCode>\n" + bindings + "    </RmHLSLShader>\n";
}

std::string pass(const std::string& name, int index, const std::string& target, int cullMode, const std::string& body) {
    const std::string renderTarget =
        target.empty() ? "" : "    <RmRenderTarget NAME=\"" + target + "\" API=\"\" INDEX=\"0\" RENDER_TO_SCREEN=\"FALSE\" "
                                  "COLOR_CLEAR=\"TRUE\" DEPTH_CLEAR=\"FALSE\" CLEAR_COLOR_VALUE=\"0\" DEPTH_CLEAR_VALUE=\"1.0\"/>\n";
    return "   <RmPass NAME=\"" + name + "\" API=\"D3D\" PASS_INDEX=\"" + std::to_string(index) + "\" ENABLED=\"TRUE\">\n"
           "    <RmModelReference NAME=\"Quad\" API=\"\"/>\n"
           "    <RmRenderStateBlock NAME=\"States\" API=\"D3D\">\n"
           "     <RmState NAME=\"D3DRS_ZENABLE\" API=\"D3D\" STATE=\"7\" VALUE=\"0\" USAGE=\"0\"/>\n"
           "     <RmState NAME=\"D3DRS_CULLMODE\" API=\"D3D\" STATE=\"22\" VALUE=\"" + std::to_string(cullMode) + "\" USAGE=\"0\"/>\n"
           "    </RmRenderStateBlock>\n" + body + renderTarget + "   </RmPass>\n";
}

// An RmVectorVariable holding (x, y, 0, 0).
std::string vectorVariable(const std::string& name, double x, double y) {
    return "   <RmVectorVariable NAME=\"" + name + "\" API=\"\" ARTIST_EDITABLE=\"FALSE\" VARIABLE_SEMANTIC=\"\" VALUE_0=\"" +
           std::to_string(x) + "\" VALUE_1=\"" + std::to_string(y) +
           "\" VALUE_2=\"0\" VALUE_3=\"0\" MIN=\"0\" MAX=\"100\" CLAMP=\"FALSE\" NORMALIZE=\"FALSE\"/>\n";
}

// Pass "Copy" draws the picture into target "Scene" through the quad's texture coordinates, as a
// glow's first pass draws its scene; `passes` follow it.
std::string effect(const std::string& variables, const std::string& passes) {
    const std::string copy = pass(
        "Copy", 0, "Scene", 3,
        hlsl("Vertex Shader", false, "vs_2_0",
             "struct VS_OUTPUT { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };\n"
             "VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {\n"
             "   VS_OUTPUT o; o.Pos = float4(Pos.xy, 0.0, 1.0); o.Tex = Tex; return o;\n"
             "}") +
            hlsl("Pixel Shader", true, "ps_2_0",
                 "sampler2D PictureSampler;\n"
                 "float4 main(float2 Tex : TEXCOORD0) : COLOR0 { return tex2D(PictureSampler, Tex); }",
                 "     <RmSampler NAME=\"PictureSampler\" API=\"\" REGISTER=\"0\"/>\n") +
            textureObject("PictureSampler", "Picture"));
    return "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
           "<RENDER_MONKEY>\n"
           " <RmEffectWorkspace NAME=\"W\" API=\"\" ACTIVE_EFFECT=\"W.Post\" VALIDATION_STRING=\"\" XML_VERSION=\"RenderMonkey 1.71\">\n"
           "  <RmDirectXEffect NAME=\"Post\" API=\"D3D\" ACTIVE_CAMERA=\"\">\n"
           "   <Rm2DTextureVariable NAME=\"Picture\" API=\"\" ARTIST_EDITABLE=\"FALSE\" VARIABLE_SEMANTIC=\"\" FILE_NAME=\"picture.png\" ORIGIN=\"0\"/>\n"
           "   <RmRenderableTexture NAME=\"Scene\" API=\"\" ARTIST_EDITABLE=\"FALSE\" VARIABLE_SEMANTIC=\"\" FILE_NAME=\"\" ORIGIN=\"0\" "
           "WIDTH=\"256\" HEIGHT=\"256\" FORMAT=\"113\" USE_VIEWPORT_DIMENSIONS=\"TRUE\" GENERATE_MIPMAPS=\"FALSE\" WIDTH_RATIO=\"1.0\" HEIGHT_RATIO=\"1.0\"/>\n"
           "   <RmModelData NAME=\"Quad\" API=\"\" FILE_NAME=\"ScreenAlignedQuad.3ds\" ORIENTATION=\"0\"/>\n" +
           variables + copy + passes +
           "  </RmDirectXEffect>\n"
           " </RmEffectWorkspace>\n"
           "</RENDER_MONKEY>\n";
}

// What Direct3D 9 leaves in "Scene": the picture filtered at the quad's texture coordinates.
RefImage expectedScene() {
    const RefImage picture = topFirstPicture();
    RefImage scene(kWidth, kHeight);
    for (int r = 0; r < kHeight; ++r)
        for (int x = 0; x < kWidth; ++x) scene.at(x, r) = sampleBilinear(picture, quadUv(x, r, kWidth, kHeight));
    return scene;
}

class Direct3DTextureSpaceGLTest : public GlTest {
protected:
    // Writes the picture, the quad and the effect, renders it at kWidth x kHeight and returns the
    // output, top row first.
    Image render(const std::string& rfx) {
        writePicture(media_ / "picture.png");
        writeScreenAlignedQuad(media_ / "ScreenAlignedQuad.3ds");
        Result<Workspace> loaded = loadWorkspace(media_.write("post.rfx", rfx));
        if (!loaded.ok()) {
            ADD_FAILURE() << formatAll(loaded.diagnostics());
            return {};
        }
        EXPECT_EQ(loaded->textureSpace, TextureSpace::Direct3D9);
        GlRun run = runWorkspace(std::make_unique<Workspace>(std::move(*loaded)), RunSettings{{kWidth, kHeight}});
        if (!run.exec) return {};
        return readBack(*run.exec, run.ws->outputTargetName());
    }

    // The worst distance of the output (top row first) from `expected` (row index from the top),
    // rgba; the failure names the first pixel that is out.
    void compare(const Image& image, const RefImage& expected, double tolerance) {
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);
        double worst = 0.0;
        std::string first;
        for (int r = 0; r < kHeight; ++r)
            for (int x = 0; x < kWidth; ++x)
                for (int c = 0; c < 4; ++c) {
                    const double d = std::abs(image.at(x, r, c) - expected.at(x, r)[c]);
                    if (d > tolerance && first.empty())
                        first = "pixel (" + std::to_string(x) + ", " + std::to_string(r) + ") from the top-left, channel " +
                                std::to_string(c) + ": " + std::to_string(image.at(x, r, c)) + ", expected " +
                                std::to_string(expected.at(x, r)[c]);
                    worst = std::max(worst, d);
                }
        expectWithin("max abs error against Direct3D 9's float64 model", worst, tolerance);
        if (!first.empty()) ADD_FAILURE() << first;
    }

    ScratchDir media_;
};

// The picture filtered from 8-bit texels (llvmpipe filters them in 8-bit fixed point), stored in
// a half-float target, written to the output.
constexpr double kTolerance = 1.5 / 255.0;

// A glow's combine pass: the target through texture coordinates built from the position,
// 0.5 * (1 - Pos.y) with half a texel added (which lands D3D9's pixel on the texel's centre), and
// the picture itself through the quad's own texture coordinates. Red and green come from the
// target, blue is the picture's green (its row ramp): either read upside down, or the half pixel
// not applied, and the output differs by many steps.
TEST_F(Direct3DTextureSpaceGLTest, ATargetReadThroughPositionArithmeticAndTheImageThroughMeshUvsAgree) {
    const std::string combine = pass(
        "Combine", 1, "", 3,
        hlsl("Vertex Shader", false, "vs_2_0",
             "float2 HalfTexel;\n"
             "struct VS_OUTPUT { float4 Pos : POSITION; float2 Screen : TEXCOORD0; float2 Tex : TEXCOORD1; };\n"
             "VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {\n"
             "   VS_OUTPUT o; o.Pos = float4(Pos.xy, 0.0, 1.0);\n"
             "   o.Screen = float2(0.5 * (1.0 + Pos.x), 0.5 * (1.0 - Pos.y)) + HalfTexel;\n"
             "   o.Tex = Tex; return o;\n"
             "}",
             "     <RmShaderConstant NAME=\"HalfTexel\" API=\"\" REGISTER=\"0\"/>\n") +
            hlsl("Pixel Shader", true, "ps_2_0",
                 "sampler2D SceneSampler; sampler2D PictureSampler;\n"
                 "float4 main(float2 Screen : TEXCOORD0, float2 Tex : TEXCOORD1) : COLOR0 {\n"
                 "   float4 scene = tex2D(SceneSampler, Screen);\n"
                 "   float4 picture = tex2D(PictureSampler, Tex);\n"
                 "   return float4(scene.r, scene.g, picture.g, 1.0);\n"
                 "}",
                 "     <RmSampler NAME=\"SceneSampler\" API=\"\" REGISTER=\"0\"/>\n"
                 "     <RmSampler NAME=\"PictureSampler\" API=\"\" REGISTER=\"1\"/>\n") +
            textureObject("SceneSampler", "Scene") + textureObject("PictureSampler", "Picture"));
    const std::string halfTexel = vectorVariable("HalfTexel", 0.5 / kWidth, 0.5 / kHeight);
    const Image output = render(effect(halfTexel, combine));
    const RefImage scene = expectedScene();
    const RefImage picture = topFirstPicture();
    RefImage expected(kWidth, kHeight);
    for (int r = 0; r < kHeight; ++r)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec2 screen = glm::dvec2(0.5 * (1.0 + (2.0 * x / kWidth - 1.0)), 0.5 * (1.0 - (1.0 - 2.0 * r / kHeight))) +
                                      glm::dvec2(0.5 / kWidth, 0.5 / kHeight);
            const glm::dvec4 s = sampleBilinear(scene, screen);
            const glm::dvec4 p = sampleBilinear(picture, quadUv(x, r, kWidth, kHeight));
            expected.at(x, r) = glm::dvec4(s.r, s.g, p.g, 1.0);
        }
    compare(output, expected, kTolerance);
}

// ps_3_0 reads the same target twice: at its VPOS, Direct3D 9's whole-number pixel position
// ((vPos + 0.5) / size is the texel's centre), and through the quad's texture coordinates with half
// a texel added; both give the texel under the pixel. Blue is VPOS.y / height (row 0 at the top)
// and alpha is 1 where VFACE says the face is a front face (clockwise on the screen), with culling
// off so that a back face would show.
TEST_F(Direct3DTextureSpaceGLTest, AVposReadAndAMeshUvReadOfOneTargetAgree) {
    const std::string show = pass(
        "Show", 1, "", 1,
        hlsl("Vertex Shader", false, "vs_3_0",
             "float2 HalfTexel;\n"
             "struct VS_OUTPUT { float4 Pos : POSITION; float2 Tex : TEXCOORD0; };\n"
             "VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {\n"
             "   VS_OUTPUT o; o.Pos = float4(Pos.xy, 0.0, 1.0); o.Tex = Tex + HalfTexel; return o;\n"
             "}",
             "     <RmShaderConstant NAME=\"HalfTexel\" API=\"\" REGISTER=\"0\"/>\n") +
            hlsl("Pixel Shader", true, "ps_3_0",
                 "sampler2D SceneSampler; float2 Size;\n"
                 "float4 main(float2 Tex : TEXCOORD0, float2 vPos : VPOS, float face : VFACE) : COLOR0 {\n"
                 "   float4 byPosition = tex2D(SceneSampler, (vPos + 0.5) / Size);\n"
                 "   float4 byMesh = tex2D(SceneSampler, Tex);\n"
                 "   return float4(byPosition.g, byMesh.g, vPos.y / Size.y, face > 0.0 ? 1.0 : 0.25);\n"
                 "}",
                 "     <RmSampler NAME=\"SceneSampler\" API=\"\" REGISTER=\"0\"/>\n"
                 "     <RmShaderConstant NAME=\"Size\" API=\"\" REGISTER=\"0\"/>\n") +
            textureObject("SceneSampler", "Scene"));
    const std::string variables = vectorVariable("HalfTexel", 0.5 / kWidth, 0.5 / kHeight) + vectorVariable("Size", kWidth, kHeight);
    const Image output = render(effect(variables, show));
    const RefImage scene = expectedScene();
    RefImage expected(kWidth, kHeight);
    for (int r = 0; r < kHeight; ++r)
        for (int x = 0; x < kWidth; ++x) {
            const double texel = scene.at(x, r).g;
            expected.at(x, r) = glm::dvec4(texel, texel, double(r) / kHeight, 1.0);
        }
    compare(output, expected, kTolerance);
}

}  // namespace
}  // namespace rmfx::test
