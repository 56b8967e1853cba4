// The RenderMonkey importer: what passes read and write, variables of every type and scope, textures,
// samplers and their states, vertex streams, renderable textures and models.

#include "frontend/rfx/RfxImporter.h"

#include <gtest/gtest.h>

#include "RfxImporterTestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

TEST(RfxImporterInputs, SamplerStatesAndStreams) {
    Workspace ws = imported("gl_legacy.rfx");
    const Pass& show = ws.passes[1];
    ASSERT_EQ(show.samplers.size(), 1u);
    const Sampler& s = show.samplers[0];
    EXPECT_EQ(s.uniform, "Scene");
    EXPECT_EQ(s.target, "Scene");  // a renderable texture
    EXPECT_EQ(s.texture, "");
    EXPECT_EQ(s.wrapS, Wrap::Clamp);   // 2 GL_CLAMP_TO_EDGE
    EXPECT_EQ(s.wrapT, Wrap::Mirror);  // 5 GL_MIRRORED_REPEAT
    EXPECT_EQ(s.filter, Filter::Nearest);
    EXPECT_EQ(s.mipmap, MipmapMode::None);

    ASSERT_EQ(show.streams.size(), 4u);
    EXPECT_EQ(show.streams[0].usage, VertexUsage::Position);
    EXPECT_EQ(show.streams[1].usage, VertexUsage::Normal);
    EXPECT_EQ(show.streams[2].usage, VertexUsage::TexCoord);
    EXPECT_EQ(show.streams[3].usage, VertexUsage::Tangent);
    // OpenGL: built-ins, except the attribute the vertex shader declares.
    EXPECT_EQ(show.streams[0].attribute, "");
    EXPECT_EQ(show.streams[2].attribute, "");
    EXPECT_EQ(show.streams[3].attribute, "rm_Tangent");
}

TEST(RfxImporterInputs, VariablesOfEveryTypeWithScopesSemanticsAndRanges) {
    Workspace ws = imported("gl_legacy.rfx");
    // Scale: workspace 0.75, group 0.5 (the group's wins), pass "Tint" 0.5 as a pass constant.
    EXPECT_FLOAT_EQ(variable(ws, "Scale").value.asFloat(), 0.5f);
    EXPECT_FLOAT_EQ(*variable(ws, "Scale").max, 2.0f);
    EXPECT_TRUE(variable(ws, "Scale").editable);
    ASSERT_EQ(ws.passes[0].constants.size(), 1u);
    EXPECT_EQ(ws.passes[0].constants[0].name, "Scale");
    EXPECT_FALSE(ws.passes[0].constants[0].editable);
    EXPECT_FLOAT_EQ(variable(ws, "Shadowed").value.asFloat(), 0.0f);  // the effect's, not the workspace's 1.0
    EXPECT_EQ(ws.findVariable("Width"), nullptr);                      // registry state is no variable

    const Variable& tint = variable(ws, "Tint");
    EXPECT_EQ(tint.value.type, ValueType::Color4);
    expectColor({tint.value.data[0], tint.value.data[1], tint.value.data[2], tint.value.data[3]}, {0.2f, 0.4f, 0.6f, 1.0f});
    const Variable& offset = variable(ws, "Offset");
    EXPECT_EQ(offset.value.type, ValueType::Vec4);
    EXPECT_FLOAT_EQ(offset.value.data[1], 0.125f);
    EXPECT_FLOAT_EQ(*offset.min, -1.0f);
    EXPECT_EQ(variable(ws, "Time").semantic, "Time0_X");
    EXPECT_FALSE(variable(ws, "Time").editable);
    EXPECT_EQ(variable(ws, "Steps").value.type, ValueType::Int);
    EXPECT_EQ(variable(ws, "Steps").value.asInt(), -3);
    EXPECT_EQ(variable(ws, "Flag").value.type, ValueType::Bool);
    EXPECT_TRUE(variable(ws, "Flag").value.asBool());
    const Variable& basis = variable(ws, "Basis");
    EXPECT_EQ(basis.value.type, ValueType::Mat4);
    EXPECT_EQ(basis.semantic, "ViewProjection");
    for (int i = 0; i < 16; ++i) EXPECT_FLOAT_EQ(basis.value.data[i], static_cast<float>(i + 1));

    const Variable& pair = variable(ws, "Pair");
    EXPECT_EQ(pair.value.type, ValueType::Vec2);
    EXPECT_FLOAT_EQ(pair.value.data[0], 0.5f);
    EXPECT_FLOAT_EQ(pair.value.data[1], -1.5f);
    EXPECT_EQ(variable(ws, "Triple").value.type, ValueType::Vec3);
    EXPECT_EQ(variable(ws, "Triple").semantic, "ViewPosition");
    EXPECT_FLOAT_EQ(variable(ws, "Triple").value.data[2], 3.0f);
    // Column-major: (row r, column c) is element c * rows + r.
    const Variable& m2 = variable(ws, "Rotation2");
    EXPECT_EQ(m2.value.type, ValueType::Mat2);
    EXPECT_EQ(std::vector<float>(m2.value.data.begin(), m2.value.data.begin() + 4), (std::vector<float>{1, 3, 2, 4}));
    const Variable& m3 = variable(ws, "Rotation3");
    EXPECT_EQ(m3.value.type, ValueType::Mat3);
    EXPECT_FLOAT_EQ(m3.value.data[5], 7.0f);  // row 2, column 1
    EXPECT_FLOAT_EQ(m3.value.data[7], 5.0f);  // row 1, column 2
    EXPECT_FLOAT_EQ(m3.value.data[0], 0.0f);
    EXPECT_EQ(variable(ws, "Count").value.type, ValueType::Int);
    EXPECT_EQ(variable(ws, "Count").value.asInt(), 6);
}

TEST(RfxImporterInputs, TexturesKeepFileNamesAsWritten) {
    Workspace ws = imported("gl_legacy.rfx", "Other");
    EXPECT_EQ(ws.textures.size(), 2u);  // "Unused", which no pass samples, is left out
    const Texture* noise = ws.findTexture("Noise");
    ASSERT_NE(noise, nullptr);
    EXPECT_EQ(noise->kind, TextureKind::Texture2D);
    EXPECT_EQ(noise->files, std::vector<std::string>{"..\\Media\\Textures\\NoiseVolume.TGA"});
    const Texture* sky = ws.findTexture("Sky");
    ASSERT_NE(sky, nullptr);
    EXPECT_EQ(sky->kind, TextureKind::Cube);
    EXPECT_EQ(sky->files, std::vector<std::string>{"C:\\Program Files\\RenderMonkey\\Media\\Textures\\Snow.dds"});
    EXPECT_EQ(ws.findTexture("Volume"), nullptr);  // a volume texture no pass samples: left out like "Unused"
    EXPECT_EQ(allWarnings("gl_legacy.rfx", "Other").find("Rm3DTextureVariable"), std::string::npos);
}

TEST(RfxImporterInputs, GlSamplerStatesOfTextureVariables) {
    Workspace ws = imported("gl_legacy.rfx", "Other");
    const Pass& only = ws.passes[0];
    ASSERT_EQ(only.samplers.size(), 2u);
    const Sampler& noise = only.samplers[0];  // no states: OpenGL's defaults
    EXPECT_EQ(noise.texture, "Noise");
    EXPECT_EQ(noise.wrapS, Wrap::Repeat);
    EXPECT_EQ(noise.wrapT, Wrap::Repeat);
    EXPECT_EQ(noise.filter, Filter::Linear);
    EXPECT_EQ(noise.mipmap, MipmapMode::Linear);
    const Sampler& sky = only.samplers[1];
    EXPECT_EQ(sky.texture, "Sky");
    EXPECT_EQ(sky.filter, Filter::Linear);      // magnify 1; minify 4 is NEAREST_MIPMAP_LINEAR
    EXPECT_EQ(sky.mipmap, MipmapMode::Linear);  // from the minify filter
    expectColor(sky.border, {0.0f, 0.0f, 1.0f, 1.0f});  // -16776961 = 0xFF0000FF
    std::string warnings = allWarnings("gl_legacy.rfx", "Other");
    int line = lineOf(rfxDir() / "gl_legacy.rfx", "<RmTextureObject NAME=\"Sky\"");
    const std::string file = (rfxDir() / "gl_legacy.rfx").string();
    EXPECT_TRUE(test::hasLine(warnings, file + ":" + std::to_string(line) +
                                            ": warning: <RmTextureObject NAME=\"Sky\">: minify and "
                                            "magnify filters differ; rmfx samplers have one filter: the "
                                            "magnify one is used"))
        << warnings;
    EXPECT_EQ(sky.wrapR, Wrap::Clamp);  // GL_TextureWrapR 1 (GL_CLAMP), kept for volumes; a cube map ignores it
    EXPECT_EQ(warnings.find("R wrap"), std::string::npos) << warnings;
    // 1082130432 = 0x40800000 = 4.0f
    EXPECT_TRUE(test::hasLine(warnings, file + ":" + std::to_string(lineOf(file, "GL_TextureMaxAnisotropyEXT")) +
                                            ": warning: <RmState NAME=\"GL_TextureMaxAnisotropyEXT\">: sampler state "
                                            "GL_TextureMaxAnisotropyEXT = 4 has no equivalent in rmfx's sampler model; ignored"))
        << warnings;
}

TEST(RfxImporterInputs, RenderableTexturesTakeEveryD3dFormatNumber) {
    Workspace ws = imported("gl_legacy.rfx");
    auto format = [&](const std::string& name) {
        const RenderTarget* t = ws.findTarget(name);
        EXPECT_NE(t, nullptr) << name;
        return t ? t->format : TargetFormat::RGBA8;
    };
    EXPECT_EQ(format("Scene"), TargetFormat::RGBA16F);  // 113
    EXPECT_EQ(format("Half"), TargetFormat::RGBA8);     // 21
    EXPECT_EQ(format("F34"), TargetFormat::RG16);
    EXPECT_EQ(format("F36"), TargetFormat::RGBA16);
    EXPECT_EQ(format("F111"), TargetFormat::R16F);
    EXPECT_EQ(format("F112"), TargetFormat::RG16F);
    EXPECT_EQ(format("F114"), TargetFormat::R32F);
    EXPECT_EQ(format("F115"), TargetFormat::RG32F);
    EXPECT_EQ(format("F116"), TargetFormat::RGBA32F);
    const RenderTarget* scene = ws.findTarget("Scene");
    EXPECT_FALSE(scene->size.relative);
    EXPECT_EQ(scene->size.width, 64);
    EXPECT_EQ(scene->size.height, 32);
    EXPECT_FALSE(scene->mipmaps);
    const RenderTarget* half = ws.findTarget("Half");
    EXPECT_TRUE(half->size.relative);
    EXPECT_DOUBLE_EQ(half->size.scaleX, 0.5);
    EXPECT_DOUBLE_EQ(half->size.scaleY, 0.25);
    EXPECT_TRUE(half->mipmaps);
}

TEST(RfxImporterInputs, ModelOrientationOtherThanZeroWarns) {
    std::string text = glEffect("<RmModelData NAME=\"M\" FILE_NAME=\"m.obj\" ORIENTATION=\"1\"/>\n"
                                "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n</RmGLPass>\n");
    std::string all = formatAll(importRfxText(text, "t.rfx", ".", {}).diagnostics());
    EXPECT_TRUE(test::hasLine(all,
                              "t.rfx:4: warning: <RmModelData NAME=\"M\">: ORIENTATION 1 is not applied: the model is drawn as "
                              "the file holds it (RenderMonkey does not document the values)"))
        << all;
    EXPECT_EQ(allWarnings("gl_legacy.rfx").find("ORIENTATION"), std::string::npos);
}

// RenderMonkey's stream maps are shared by every pass that names one: a channel a pass's shaders
// do not read is normal there (a screen-aligned quad's pass ignores the normals), not a warning.
TEST(RfxImporterInputs, SharedStreamChannelsAPassDoesNotReadAreNotWarnedAbout) {
    Result<Workspace> loaded = loadWorkspace(rfxDir() / "d3d_hlsl.rfx");  // BINORMAL2: no shader reads it
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    for (const Pass& pass : loaded->passes)
        for (const VertexStream& stream : pass.streams) EXPECT_TRUE(stream.shared);
    EXPECT_EQ(formatAll(loaded.diagnostics()).find("do not read"), std::string::npos) << formatAll(loaded.diagnostics());
}

// Texture stage states (USAGE="TEXTURE_STATE") share their numbers with the sampler states but are
// not sampler states: D3DTSS_COLOROP (1) is no D3DSAMP_ADDRESSU, and the bump matrix (7-10) reaches
// texbem instead of the mip filter.
TEST(RfxImporterInputs, TextureStageStatesAreNotSamplerStatesAndFeedTexbem) {
    const std::string text = d3dEffect(
        "<Rm2DTextureVariable NAME=\"Tex\" FILE_NAME=\"\"/>\n"
        "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
        "<RmShader NAME=\"PS\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[ps.1.1\ntex t0\ntexbem t1, t0\nmov r0, t1]]>"
        "</RmShaderCode></RmShader>\n"
        "<RmTextureObject NAME=\"bump\" STATE_INDEX=\"0\"><RmTextureReference NAME=\"Tex\"/></RmTextureObject>\n"
        "<RmTextureObject NAME=\"env\" STATE_INDEX=\"1\"><RmTextureReference NAME=\"Tex\"/>\n"
        "<RmState NAME=\"D3DTSS_COLOROP\" STATE=\"1\" VALUE=\"4\" USAGE=\"TEXTURE_STATE\"/>\n"
        "<RmState NAME=\"D3DTSS_BUMPENVMAT00\" STATE=\"7\" VALUE=\"0.500000\" USAGE=\"TEXTURE_STATE\"/>\n"
        "<RmState NAME=\"D3DTSS_BUMPENVMAT11\" STATE=\"10\" VALUE=\"1056964608\" USAGE=\"TEXTURE_STATE\"/>\n"
        "<RmState NAME=\"D3DTSS_TEXCOORDINDEX\" STATE=\"11\" VALUE=\"1\" USAGE=\"TEXTURE_STATE\"/>\n"
        "</RmTextureObject>\n</RmPass>\n");
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws.ok()) << formatAll(ws.diagnostics());
    const Pass& p = ws->passes[0];
    ASSERT_EQ(p.samplers.size(), 2u);
    EXPECT_EQ(p.samplers[1].uniform, "env");
    EXPECT_EQ(p.samplers[1].wrapS, Wrap::Repeat);  // Direct3D's default, not D3DTADDRESS_BORDER (4)
    EXPECT_EQ(p.samplers[1].mipmap, MipmapMode::None);
    const std::string& code = p.shaders[0].code;
    EXPECT_NE(code.find("rm_tc1.x + 0.5 * (t0).x + 0.0 * (t0).y, rm_tc1.y + 0.0 * (t0).x + 0.5 * (t0).y"), std::string::npos) << code;
    EXPECT_EQ(formatAll(ws.diagnostics()).find("TEXCOORDINDEX"), std::string::npos) << formatAll(ws.diagnostics());
}

// ORIGIN 0 (every public file's) is how rmfx reads images; another value is named in a warning.
TEST(RfxImporterInputs, TextureOriginOtherThanZeroIsAWarning) {
    auto effect = [](const std::string& origin) {
        return glEffect("<Rm2DTextureVariable NAME=\"T\" FILE_NAME=\"t.png\" ORIGIN=\"" + origin + "\"/>\n"
                        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
                        "<RmTextureObject NAME=\"t\"><RmTextureReference NAME=\"T\"/></RmTextureObject>\n<RmSampler NAME=\"t\"/>\n" +
                        std::string(kFragment) + "\n</RmGLPass>\n");
    };
    Result<Workspace> zero = importRfxText(effect("0"), "t.rfx", ".", {""});
    ASSERT_TRUE(zero) << formatAll(zero.diagnostics());
    EXPECT_EQ(formatAll(zero.diagnostics()).find("ORIGIN"), std::string::npos);
    Result<Workspace> one = importRfxText(effect("1"), "t.rfx", ".", {""});
    ASSERT_TRUE(one) << formatAll(one.diagnostics());
    EXPECT_TRUE(test::hasLine(formatAll(one.diagnostics()),
                              "t.rfx:4: warning: <Rm2DTextureVariable NAME=\"T\">: ORIGIN 1 is not applied: the image is read "
                              "with its first row at the top, as for ORIGIN 0, the only value public RenderMonkey files hold"))
        << formatAll(one.diagnostics());
}

// A pass may declare its own texture, renderable texture and model (RenderMonkey's assembly fur
// does), after the texture objects and shaders that use them.
TEST(RfxImporterInputs, TexturesTargetsAndModelsDeclaredInsideAPassAreThePasss) {
    const std::string text = glEffect(
        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
        "<RmTextureObject NAME=\"fur\"><RmTextureReference NAME=\"FurTexture\"/></RmTextureObject>\n"
        "<RmSampler NAME=\"fur\"/>\n"
        "<RmModelReference NAME=\"Shell\"/>\n"
        "<RmRenderTarget NAME=\"Layer\"/>\n" +
        std::string(kFragment) +
        "\n<Rm2DTextureVariable NAME=\"FurTexture\" FILE_NAME=\"fur.tga\"/>\n"
        "<RmModelData NAME=\"Shell\" FILE_NAME=\"shell.3ds\"/>\n"
        "<RmRenderableTexture NAME=\"Layer\" FORMAT=\"21\" WIDTH=\"64\" HEIGHT=\"32\"/>\n"
        "</RmGLPass>\n");
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    const Texture* fur = ws->findTexture("FurTexture");
    ASSERT_NE(fur, nullptr);
    EXPECT_EQ(fur->files, std::vector<std::string>{"fur.tga"});
    EXPECT_NE(ws->findTarget("Layer"), nullptr);
    ASSERT_EQ(ws->passes.size(), 1u);
    EXPECT_EQ(ws->passes[0].draw.file, "shell.3ds");
    EXPECT_EQ(ws->passes[0].target, "Layer");
    ASSERT_EQ(ws->passes[0].samplers.size(), 1u);
    EXPECT_EQ(ws->passes[0].samplers[0].texture, "FurTexture");
    EXPECT_EQ(formatAll(ws.diagnostics()).find("inside a pass"), std::string::npos) << formatAll(ws.diagnostics());
}

}  // namespace
}  // namespace rmfx
