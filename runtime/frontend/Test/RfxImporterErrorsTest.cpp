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
    EXPECT_NE(errorsOf(glEffect("<RmFloatVariable NAME=\"x\" VALUE=\"abc\"/>\n")).find(
                  "t.rfx:4: error: <RmFloatVariable NAME=\"x\">: attribute VALUE: 'abc' is not a number"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmRenderableTexture NAME=\"rt\" WIDTH=\"4\" HEIGHT=\"4\" FORMAT=\"999\"/>\n"))
                  .find("t.rfx:4: error: <RmRenderableTexture NAME=\"rt\">: FORMAT 999 is not a Direct3D 9 format"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmRenderableTexture NAME=\"rt\" WIDTH=\"0\" HEIGHT=\"4\" FORMAT=\"21\"/>\n"))
                  .find("t.rfx:4: error: <RmRenderableTexture NAME=\"rt\">: attribute WIDTH: 0 is outside 1…16384"),
              std::string::npos);
    // A constant naming no variable is an error when a shader uses the name, else a warning.
    std::string usedFragment = "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[uniform float Nope; "
                               "void main() { gl_FragColor = vec4(Nope); }]]></RmShaderCode></RmGLShader>\n";
    EXPECT_NE(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmShaderConstant NAME=\"Nope\"/>\n" +
                                usedFragment + "</RmGLPass>\n"))
                  .find("t.rfx:5: error: <RmShaderConstant NAME=\"Nope\">: no variable 'Nope' is visible from the pass"),
              std::string::npos);
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
    EXPECT_NE(formatAll(lenient.diagnostics()).find("<RmShaderConstant NAME=\"Nope\">: no variable 'Nope' is visible from the "
                                                    "pass (pass, effect, group or workspace); Direct3D ran with its constant "
                                                    "register unset, so it is fed zero"),
              std::string::npos)
        << formatAll(lenient.diagnostics());
    EXPECT_NE(formatAll(lenient.diagnostics()).find("<RmShaderConstant NAME=\"offsets\">: no variable 'offsets' is visible from "
                                                    "the pass (pass, effect, group or workspace); the shader declares it const"),
              std::string::npos)
        << formatAll(lenient.diagnostics());
    EXPECT_NE(formatAll(lenient.diagnostics()).find("<RmShaderConstant NAME=\"scale\">: no variable 'scale' is visible from "
                                                    "the pass (pass, effect, group or workspace); the shader declares it with an "
                                                    "initial value, which Direct3D kept and so does rmfx"),
              std::string::npos)
        << formatAll(lenient.diagnostics());
    Result<Workspace> unused = importRfxText(pass("<RmShaderConstant NAME=\"light0\"/>\n"), "t.rfx", ".");
    EXPECT_TRUE(unused.ok());
    EXPECT_NE(formatAll(unused.diagnostics()).find("t.rfx:6: warning: <RmShaderConstant NAME=\"light0\">: no variable 'light0' "
                                                 "is visible from the pass (pass, effect, group or workspace); its shaders do not use it"),
              std::string::npos) << formatAll(unused.diagnostics());
    EXPECT_NE(errorsOf(pass("<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"missing\"/></RmTextureObject>\n"))
                  .find("t.rfx:6: error: <RmTextureReference NAME=\"missing\">: no texture variable or renderable texture"),
              std::string::npos);
    // A sampler the shader reads needs its texture object; one left behind that nothing reads is
    // ignored with a warning (Ant0nin's cubemap.rfx keeps such a displacementTexture).
    const std::string sampling = "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[uniform sampler2D s; "
                                 "void main() { gl_FragColor = texture2D(s, vec2(0.5)); }]]></RmShaderCode></RmGLShader>";
    EXPECT_NE(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + sampling + "\n<RmSampler NAME=\"s\"/>\n"
                                "</RmGLPass>\n"))
                  .find("t.rfx:6: error: <RmSampler NAME=\"s\">: sampler 's' has no <RmTextureObject NAME=\"s\">"),
              std::string::npos);
    Result<Workspace> leftover = importRfxText(pass("<RmSampler NAME=\"s\"/>\n"), "t.rfx", ".");
    EXPECT_TRUE(leftover.ok()) << formatAll(leftover.diagnostics());
    EXPECT_NE(formatAll(leftover.diagnostics())
                  .find("t.rfx:6: warning: <RmSampler NAME=\"s\">: sampler 's' has no <RmTextureObject NAME=\"s\"> in the pass to "
                        "say which texture it reads; its shaders do not use it, so it is ignored"),
              std::string::npos)
        << formatAll(leftover.diagnostics());
    // The texture object is there; only its texture is missing: one error, on the reference,
    // whichever comes first.
    for (const char* order : {"<RmSampler NAME=\"s\"/>\n<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"Noise\"/></RmTextureObject>\n",
                              "<RmTextureObject NAME=\"s\"><RmTextureReference NAME=\"Noise\"/></RmTextureObject>\n<RmSampler NAME=\"s\"/>\n"}) {
        std::string errors = errorsOf(pass(order));
        EXPECT_NE(errors.find("<RmTextureReference NAME=\"Noise\">: no texture variable or renderable texture 'Noise'"),
                  std::string::npos) << errors;
        EXPECT_EQ(errors.find("has no <RmTextureObject"), std::string::npos) << errors;
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
    EXPECT_NE(errorsOf(pass("<RmRenderStateBlock>\n<RmState NAME=\"GL_DepthFunction\" STATE=\"45\" VALUE=\"9\"/>\n</RmRenderStateBlock>\n"))
                  .find("t.rfx:7: error: <RmState NAME=\"GL_DepthFunction\">: VALUE 9 is not a compare function (it takes 1, 2, 3, 4, 5, 6, 7, 8)"),
              std::string::npos);
    EXPECT_NE(errorsOf(pass("<RmRenderStateBlock>\n<RmState NAME=\"GL_CullMode\" STATE=\"8\" VALUE=\"x1\"/>\n</RmRenderStateBlock>\n"))
                  .find("t.rfx:7: error: <RmState NAME=\"GL_CullMode\">: attribute VALUE: 'x1' is not a whole number"),
              std::string::npos);
    EXPECT_NE(errorsOf(pass("<RmRenderTarget NAME=\"nowhere\" RENDER_TO_SCREEN=\"FALSE\"/>\n"))
                  .find("t.rfx:6: error: <RmRenderTarget NAME=\"nowhere\">: no <RmRenderableTexture NAME=\"nowhere\">"),
              std::string::npos);
    EXPECT_NE(errorsOf(pass("<RmModelReference NAME=\"Teapot\"/>\n"))
                  .find("t.rfx:6: error: <RmModelReference NAME=\"Teapot\">: no <RmModelData NAME=\"Teapot\">"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"zero\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n</RmGLPass>\n"))
                  .find("t.rfx:4: error: <RmGLPass NAME=\"P\">: attribute PASS_INDEX: 'zero' is not a whole number"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\"/>\n"))
                  .find("t.rfx:4: error: <pass \"P\">: it has no shaders and no pass runs before it"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmDynamicVariable NAME=\"d\" VARIABLE_TYPE=\"INTEGER\" ROWS=\"1\" COLUMNS=\"3\"/>\n"))
                  .find("t.rfx:4: error: <RmDynamicVariable NAME=\"d\">: INTEGER 1x3 has no rmfx type"),
              std::string::npos);
    EXPECT_NE(errorsOf("<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\">\n<oops\n</RENDER_MONKEY>\n").find("t.rfx:3: error: malformed XML"),
              std::string::npos);
    EXPECT_NE(errorsOf("<workspace version=\"1\"/>\n").find("the root element must be <RENDER_MONKEY>, not <workspace>"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect(""), "W.Missing").find("error: --effect W.Missing: no effect 'W.Missing'; it has: 'W.E' (OpenGL, active)"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("")).find("t.rfx:3: error: <RmOpenGLEffect NAME=\"E\">: the effect has no passes"), std::string::npos);
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
