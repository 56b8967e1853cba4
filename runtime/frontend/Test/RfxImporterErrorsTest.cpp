// The RenderMonkey importer on bad input: each mistake an error (or, where RenderMonkey ran anyway, a
// warning) with its file and line; truncated and damaged files never crash it.

#include "frontend/rfx/RfxImporter.h"

#include <gtest/gtest.h>

#include "RfxImporterTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

TEST(RfxImporterErrors, BadInputsAreErrorsWithFileAndLine) {
    auto pass = [](const std::string& inside) {
        return glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n" +
                        inside + "</RmGLPass>\n");
    };
    EXPECT_EQ(errorsOf(glEffect("<RmFloatVariable NAME=\"x\" VALUE=\"abc\"/>\n")),
              test::lines({"t.rfx:4: error: <RmFloatVariable NAME=\"x\">: attribute VALUE: 'abc' is not a number",
                           "t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
    EXPECT_EQ(errorsOf(glEffect("<RmRenderableTexture NAME=\"rt\" WIDTH=\"4\" HEIGHT=\"4\" FORMAT=\"999\"/>\n")),
              test::lines(
                  {"t.rfx:4: error: <RmRenderableTexture NAME=\"rt\">: FORMAT 999 is not a Direct3D 9 format rmfx can render to "
                   "(21 A8R8G8B8, 34 G16R16, 36 A16B16G16R16, 111 R16F, 112 G16R16F, 113 A16B16G16R16F, 114 R32F, "
                   "115 G32R32F, 116 A32B32G32R32F, …)",
                   "t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
    EXPECT_EQ(errorsOf(glEffect("<RmRenderableTexture NAME=\"rt\" WIDTH=\"0\" HEIGHT=\"4\" FORMAT=\"21\"/>\n")),
              test::lines({"t.rfx:4: error: <RmRenderableTexture NAME=\"rt\">: attribute WIDTH: 0 is outside 1…16384",
                           "t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
    // A constant naming no variable is an error when a shader uses the name, else a warning.
    std::string usedFragment = "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[uniform float Nope; "
                               "void main() { gl_FragColor = vec4(Nope); }]]></RmShaderCode></RmGLShader>\n";
    EXPECT_EQ(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmShaderConstant NAME=\"Nope\"/>\n" +
                                usedFragment + "</RmGLPass>\n")),
              test::lines({"t.rfx:5: error: <RmShaderConstant NAME=\"Nope\">: no variable 'Nope' is visible from the pass "
                           "(pass, effect, group or workspace)"}));
    // In a Direct3D pass the same is a warning: Direct3D ran with the register unset (zero), and a
    // shader const keeps the value its declaration gives.
    const std::string d3dShader = "<RmHLSLShader NAME=\"PS\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\">"
                                  "<RmShaderConstant NAME=\"Nope\"/><RmShaderConstant NAME=\"offsets\"/>"
                                  "<RmShaderConstant NAME=\"scale\"/><RmShaderCode><![CDATA["
                                  "static const float2 offsets[2] = { float2(1, 0), float2(0, 1) };\nfloat4 Nope;\n"
                                  "float scale = 1.0 / 2048.0;\n"
                                  "float4 main() : COLOR { return Nope + offsets[1].y * scale; }]]></RmShaderCode></RmHLSLShader>";
    Result<Workspace> lenient = importRfxText(d3dEffect(d3dStatePass(1, "") + "<RmPass NAME=\"Q\" PASS_INDEX=\"0\">" +
                                                        d3dShader + "</RmPass>\n"),
                                              "t.rfx", ".", {""});
    EXPECT_TRUE(lenient.ok()) << formatAll(lenient.diagnostics());
    EXPECT_TRUE(test::hasLine(formatAll(lenient.diagnostics()),
                              "t.rfx:5: warning: <RmShaderConstant NAME=\"Nope\">: no variable 'Nope' is visible from the "
                              "pass (pass, effect, group or workspace); Direct3D ran with its constant "
                              "register unset, so it is fed zero"))
        << formatAll(lenient.diagnostics());
    EXPECT_TRUE(test::hasLine(formatAll(lenient.diagnostics()),
                              "t.rfx:5: warning: <RmShaderConstant NAME=\"offsets\">: no variable 'offsets' is visible from "
                              "the pass (pass, effect, group or workspace); the shader declares it const, with its own "
                              "value, which it keeps"))
        << formatAll(lenient.diagnostics());
    EXPECT_TRUE(test::hasLine(formatAll(lenient.diagnostics()),
                              "t.rfx:5: warning: <RmShaderConstant NAME=\"scale\">: no variable 'scale' is visible from "
                              "the pass (pass, effect, group or workspace); the shader declares it with an "
                              "initial value, which Direct3D kept and so does rmfx"))
        << formatAll(lenient.diagnostics());
    Result<Workspace> unused = importRfxText(pass("<RmShaderConstant NAME=\"light0\"/>\n"), "t.rfx", ".");
    EXPECT_TRUE(unused.ok());
    EXPECT_TRUE(test::hasLine(formatAll(unused.diagnostics()),
                              "t.rfx:6: warning: <RmShaderConstant NAME=\"light0\">: no variable 'light0' "
                              "is visible from the pass (pass, effect, group or workspace); its shaders do not use it, "
                              "so it is ignored"))
        << formatAll(unused.diagnostics());
    EXPECT_EQ(errorsOf(pass("<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"missing\"/></RmTextureObject>\n")),
              test::lines({"t.rfx:6: error: <RmTextureReference NAME=\"missing\">: no texture variable or renderable texture "
                           "'missing' is visible from the pass"}));
    // A sampler the shader reads needs its texture object; one left behind that nothing reads is
    // ignored with a warning (Ant0nin's cubemap.rfx keeps such a displacementTexture).
    const std::string sampling = "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[uniform sampler2D s; "
                                 "void main() { gl_FragColor = texture2D(s, vec2(0.5)); }]]></RmShaderCode></RmGLShader>";
    EXPECT_EQ(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + sampling +
                                "\n<RmSampler NAME=\"s\"/>\n"
                                "</RmGLPass>\n")),
              test::lines({"t.rfx:6: error: <RmSampler NAME=\"s\">: sampler 's' has no <RmTextureObject NAME=\"s\"> in the pass "
                           "to say which texture it reads"}));
    Result<Workspace> leftover = importRfxText(pass("<RmSampler NAME=\"s\"/>\n"), "t.rfx", ".");
    EXPECT_TRUE(leftover.ok()) << formatAll(leftover.diagnostics());
    EXPECT_TRUE(
        test::hasLine(formatAll(leftover.diagnostics()),
                      "t.rfx:6: warning: <RmSampler NAME=\"s\">: sampler 's' has no <RmTextureObject NAME=\"s\"> in the pass to "
                      "say which texture it reads; its shaders do not use it, so it is ignored"))
        << formatAll(leftover.diagnostics());
    // The texture object is there; only its texture is missing: one error, on the reference,
    // whichever comes first.
    for (const auto& [order, line] :
         {std::pair{
              "<RmSampler NAME=\"s\"/>\n<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"Noise\"/></RmTextureObject>\n", 7},
          std::pair{
              "<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"Noise\"/></RmTextureObject>\n<RmSampler NAME=\"s\"/>\n",
              6}}) {
        EXPECT_EQ(errorsOf(pass(order)),
                  test::lines({"t.rfx:" + std::to_string(line) +
                               ": error: <RmTextureReference NAME=\"Noise\">: no "
                               "texture variable or renderable texture 'Noise' is visible from the pass"}));
    }
    // A 3D texture (RenderMonkey's NoiseVolume.dds, in many real files) is a volume texture.
    Result<Workspace> volume = importRfxText(glEffect(
        "<Rm3DTextureVariable NAME=\"Noise\" FILE_NAME=\"NoiseVolume.dds\"/>\n"
        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
        "<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"Noise\"/>"
        "<RmState NAME=\"GL_TextureWrapR\" STATE=\"32882\" VALUE=\"2\"/></RmTextureObject>\n<RmSampler NAME=\"s\"/>\n" +
        std::string(kFragment) + "\n</RmGLPass>\n"), "t.rfx", ".", {""});
    ASSERT_TRUE(volume) << formatAll(volume.diagnostics());
    const Texture* noise = volume->findTexture("Noise");
    ASSERT_NE(noise, nullptr);
    EXPECT_EQ(noise->kind, TextureKind::Volume);
    EXPECT_EQ(noise->files, std::vector<std::string>{"NoiseVolume.dds"});
    ASSERT_EQ(volume->passes.size(), 1u);
    ASSERT_EQ(volume->passes[0].samplers.size(), 1u);
    EXPECT_EQ(volume->passes[0].samplers[0].wrapR, Wrap::Clamp);  // 2: clamp to edge
    EXPECT_EQ(volume->passes[0].samplers[0].wrapS, Wrap::Repeat);
    EXPECT_EQ(
        errorsOf(
            pass("<RmRenderStateBlock>\n<RmState NAME=\"GL_DepthFunction\" STATE=\"45\" VALUE=\"9\"/>\n</RmRenderStateBlock>\n")),
        test::lines({"t.rfx:7: error: <RmState NAME=\"GL_DepthFunction\">: VALUE 9 is not a compare function (it takes 1, 2, 3, "
                     "4, 5, 6, 7, 8)"}));
    EXPECT_EQ(
        errorsOf(pass("<RmRenderStateBlock>\n<RmState NAME=\"GL_CullMode\" STATE=\"8\" VALUE=\"x1\"/>\n</RmRenderStateBlock>\n")),
        test::lines({"t.rfx:7: error: <RmState NAME=\"GL_CullMode\">: attribute VALUE: 'x1' is not a whole number"}));
    EXPECT_EQ(errorsOf(pass("<RmRenderTarget NAME=\"nowhere\" RENDER_TO_SCREEN=\"FALSE\"/>\n")),
              test::lines({"t.rfx:6: error: <RmRenderTarget NAME=\"nowhere\">: no <RmRenderableTexture NAME=\"nowhere\"> is "
                           "visible from the pass"}));
    EXPECT_EQ(errorsOf(pass("<RmModelReference NAME=\"Teapot\"/>\n")),
              test::lines({"t.rfx:6: error: <RmModelReference NAME=\"Teapot\">: no <RmModelData NAME=\"Teapot\"> is visible from "
                           "the pass"}));
    EXPECT_EQ(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"zero\" ENABLED=\"TRUE\">\n" + std::string(kFragment) +
                                "\n</RmGLPass>\n")),
              test::lines({"t.rfx:4: error: <RmGLPass NAME=\"P\">: attribute PASS_INDEX: 'zero' is not a whole number",
                           "t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
    EXPECT_EQ(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\"/>\n")),
              test::lines({"t.rfx:4: error: <pass \"P\">: it has no shaders and no pass runs before it to lend its program"}));
    EXPECT_EQ(errorsOf(glEffect("<RmDynamicVariable NAME=\"d\" VARIABLE_TYPE=\"INTEGER\" ROWS=\"1\" COLUMNS=\"3\"/>\n")),
              test::lines({"t.rfx:4: error: <RmDynamicVariable NAME=\"d\">: INTEGER 1x3 has no rmfx type (floats: 1xN vectors, "
                           "2x2, 3x3, 4x4 matrices; integers and booleans: 1x1)",
                           "t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
    EXPECT_EQ(errorsOf("<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\">\n<oops\n</RENDER_MONKEY>\n"),
              test::lines({"t.rfx:3: error: malformed XML: bad element syntax (a stray '<'? in text write &lt;)"}));
    EXPECT_EQ(errorsOf("<workspace version=\"1\"/>\n"),
              test::lines({"t.rfx:1: error: the root element must be <RENDER_MONKEY>, not <workspace>"}));
    EXPECT_EQ(errorsOf(glEffect(""), "W.Missing"),
              test::lines({"t.rfx: error: --effect W.Missing: no effect 'W.Missing'; it has: 'W.E' (OpenGL, active)"}));
    EXPECT_EQ(errorsOf(glEffect("")), test::lines({"t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"}));
}

// Every prefix of the test files, and copies with bytes overwritten, must give diagnostics or a
// workspace, never a crash (the fuzz target covers this at scale; this keeps it in the unit run).
TEST(RfxImporterErrors, TruncatedAndDamagedFilesNeverCrash) {
    for (const char* name : {"gl_legacy.rfx", "gles.rfx", "d3d_hlsl.rfx"}) {
        std::string text = test::readText(rfxDir() / name);
        ASSERT_FALSE(text.empty());
        for (size_t cut = 0; cut < text.size(); cut += 53) {
            Result<Workspace> p = importRfxText(text.substr(0, cut), "t.rfx", ".");
            EXPECT_TRUE(p.ok() || hasErrors(p.diagnostics())) << name << " cut at " << cut;
        }
        unsigned seed = 12345;
        for (int round = 0; round < 300; ++round) {
            std::string damaged = text;
            for (int k = 0; k < 4; ++k) {
                seed = seed * 1103515245u + 12345u;
                size_t at = (seed >> 8) % damaged.size();
                damaged[at] = "<>\"=&;]x9-. \n"[(seed >> 4) % 14];
            }
            Result<Workspace> p = importRfxText(damaged, "t.rfx", ".");
            EXPECT_TRUE(p.ok() || hasErrors(p.diagnostics())) << name << " round " << round;
        }
    }
}

}  // namespace
}  // namespace rmfx
