// The RenderMonkey importer, field by field, on the .rfx files written for these tests
// (tests/rfx/): every expected number below is worked out by hand from the file's text.

#include "frontend/rfx/RfxImporter.h"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "frontend/workspace/VariableValueWriter.h"
#include "model/OrbitCamera.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

std::filesystem::path rfxDir() { return test::sourceDir() / "tests" / "rfx"; }

// The 1-based line of the first line of `file` holding `needle`; 0 when none does.
int lineOf(const std::filesystem::path& file, const std::string& needle) {
    std::ifstream in(file);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (line.find(needle) != std::string::npos) return n;
    return 0;
}

Workspace imported(const std::string& name, const std::string& effect = "") {
    Result<Workspace> p = importRfxFile(rfxDir() / name, {effect});
    EXPECT_FALSE(hasErrors(p.diagnostics())) << formatAll(p.diagnostics());
    EXPECT_TRUE(p.ok());
    return p ? *p : Workspace{};
}

std::string allWarnings(const std::string& name, const std::string& effect = "") {
    return formatAll(importRfxFile(rfxDir() / name, {effect}).diagnostics());
}

const Variable& variable(const Workspace& ws, const std::string& name) {
    const Variable* v = ws.findVariable(name);
    EXPECT_NE(v, nullptr) << name;
    static Variable none;
    return v ? *v : none;
}

void expectColor(glm::vec4 actual, glm::vec4 expected) {
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(actual[i], expected[i]) << "component " << i;
}

// Errors of an .rfx text (named t.rfx): its formatted diagnostics.
std::string errorsOf(const std::string& text, const std::string& effect = "") {
    Result<Workspace> p = importRfxText(text, "t.rfx", ".", {effect});
    EXPECT_FALSE(p.ok());
    return formatAll(p.diagnostics());
}

// An OpenGL effect "E" in workspace "W" whose body starts on line 4.
std::string glEffect(const std::string& body) {
    return "<RENDER_MONKEY>\n"
           "<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
           "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\">\n" +
           body + "</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

const char* kFragment =
    "<RmGLShader NAME=\"F\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[void main() { gl_FragColor = vec4(1.0); }]]>"
    "</RmShaderCode></RmGLShader>";

TEST(RfxImporter, GlEffectPassesRunInPassIndexOrderWithTheirTargetsAndClears) {
    Workspace ws = imported("gl_legacy.rfx");
    EXPECT_EQ(ws.name, "Tests.Group.Legacy");
    EXPECT_EQ(ws.profile, GlProfile::Compatibility);
    EXPECT_EQ(ws.output.transform, DisplayTransform::None);
    EXPECT_EQ(ws.output.format, TargetFormat::RGBA8);
    ASSERT_EQ(ws.passes.size(), 3u);
    EXPECT_EQ(ws.passes[0].name, "Tint");  // PASS_INDEX 0, second in the file
    EXPECT_EQ(ws.passes[1].name, "Show");
    EXPECT_EQ(ws.passes[2].name, "Again");
    EXPECT_TRUE(ws.passes[0].enabled);
    EXPECT_FALSE(ws.passes[2].enabled);

    const Pass& tint = ws.passes[0];
    EXPECT_EQ(tint.target, "Scene");
    ASSERT_TRUE(tint.clear.color.has_value());
    expectColor(*tint.clear.color, {0.0f, 128.0f / 255.0f, 0.0f, 1.0f});  // -16744448 = 0xFF008000
    ASSERT_TRUE(tint.clear.depth.has_value());
    EXPECT_FLOAT_EQ(*tint.clear.depth, 0.75f);
    EXPECT_EQ(tint.draw.file, "quad.obj");
    EXPECT_EQ(tint.where.line, lineOf(rfxDir() / "gl_legacy.rfx", "NAME=\"Tint\" API=\"OpenGL\""));

    EXPECT_EQ(ws.passes[1].target, "");  // no RmRenderTarget: the output
    EXPECT_EQ(ws.passes[2].target, "");  // RENDER_TO_SCREEN
    // RenderMonkey clears its back buffer every frame: the first pass drawing to the output does,
    // to opaque black and depth 1; later ones clear only what they ask for.
    ASSERT_TRUE(ws.passes[1].clear.color.has_value());
    expectColor(*ws.passes[1].clear.color, {0.0f, 0.0f, 0.0f, 1.0f});
    ASSERT_TRUE(ws.passes[1].clear.depth.has_value());
    EXPECT_FLOAT_EQ(*ws.passes[1].clear.depth, 1.0f);
    EXPECT_FALSE(ws.passes[2].clear.color.has_value());
}

TEST(RfxImporter, GlRenderStatesMapToBlendDepthAndRaster) {
    Workspace ws = imported("gl_legacy.rfx");
    const Pass& tint = ws.passes[0];
    EXPECT_TRUE(tint.depth.test);
    EXPECT_TRUE(tint.depth.write);  // RenderMonkey's default, not changed by the block
    EXPECT_EQ(tint.depth.func, CompareFunc::Always);  // 8
    EXPECT_FALSE(tint.blend.enabled);
    EXPECT_EQ(tint.blend.srcColor, BlendFactor::SrcAlpha);          // 7
    EXPECT_EQ(tint.blend.dstColor, BlendFactor::OneMinusSrcAlpha);  // 8
    EXPECT_EQ(tint.blend.srcAlpha, BlendFactor::One);               // 2
    EXPECT_EQ(tint.blend.dstAlpha, BlendFactor::Zero);              // 1
    EXPECT_EQ(tint.blend.colorOp, BlendOp::Max);                    // 5
    EXPECT_EQ(tint.blend.alphaOp, BlendOp::Max);
    expectColor(tint.blend.constant, {1.0f, 64.0f / 255.0f, 0.0f, 128.0f / 255.0f});  // 0x80FF4000
    EXPECT_EQ(tint.raster.cull, CullFace::None);

    const Pass& show = ws.passes[1];
    EXPECT_FALSE(show.depth.test);
    EXPECT_FALSE(show.depth.write);
    EXPECT_EQ(show.raster.cull, CullFace::Back);  // 3
    EXPECT_TRUE(show.raster.frontCounterClockwise);

    // GL_LineWidth holds the bits of 2.5f (0x40200000 = 1075838976).
    EXPECT_EQ(show.raster.lineWidth, 2.5f);
    EXPECT_EQ(allWarnings("gl_legacy.rfx").find("GL_LineWidth"), std::string::npos) << allWarnings("gl_legacy.rfx");
}

TEST(RfxImporter, RenderStatesCarryOverInRunOrderFromThePassesThatRun) {
    Workspace ws = imported("shells.rfx");
    ASSERT_EQ(ws.passes.size(), 5u);
    std::vector<std::string> order;
    for (const Pass& p : ws.passes) order.push_back(p.name);
    EXPECT_EQ(order, (std::vector<std::string>{"Base", "Shell 1", "Reset", "Shell 2", "Shell 3"}));
    EXPECT_FALSE(ws.passes[0].blend.enabled);  // RenderMonkey's frame state
    EXPECT_TRUE(ws.passes[0].depth.test);
    for (size_t i : {1u, 3u, 4u}) {
        const Pass& p = ws.passes[i];
        EXPECT_TRUE(p.blend.enabled) << p.name;
        EXPECT_EQ(p.blend.srcColor, BlendFactor::One) << p.name;
        EXPECT_EQ(p.blend.dstColor, BlendFactor::One) << p.name;
        EXPECT_EQ(p.raster.cull, CullFace::None) << p.name;  // Reset's culling never ran
        EXPECT_TRUE(p.depth.test) << p.name;
        EXPECT_EQ(p.depth.func, CompareFunc::LessEqual) << p.name;
    }
    // The disabled pass has its own block over what it would inherit, should it be enabled.
    EXPECT_FALSE(ws.passes[2].blend.enabled);
    EXPECT_EQ(ws.passes[2].blend.dstColor, BlendFactor::One);
    EXPECT_EQ(ws.passes[2].raster.cull, CullFace::Back);
}

// A Direct3D pass with a render-state block holding `states`; the first pass has a pixel shader.
std::string d3dStatePass(int index, const std::string& states) {
    return "<RmPass NAME=\"P" + std::to_string(index) + "\" PASS_INDEX=\"" + std::to_string(index) +
           "\"><RmRenderStateBlock NAME=\"S\">" + states + "</RmRenderStateBlock>" +
           (index == 0 ? "<RmHLSLShader NAME=\"PS\" PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\">"
                         "<RmShaderCode><![CDATA[float4 main() : COLOR { return 1; }]]></RmShaderCode></RmHLSLShader>"
                       : "") +
           "</RmPass>\n";
}

std::string d3dState(int number, const std::string& value) {
    return "<RmState NAME=\"D3DRS_" + std::to_string(number) + "\" STATE=\"" + std::to_string(number) + "\" VALUE=\"" +
           value + "\"/>";
}

std::string d3dEffect(const std::string& passes) {
    return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n" +
           passes + "</RmDirectXEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
}

// Silhouette outlines: back faces drawn as lines (RenderMonkey's 1 GL_POINT, 2 GL_LINE, 3 GL_FILL)
// of a width; Direct3D's D3DRS_FILLMODE (1 point, 2 wireframe, 3 solid) sets both faces.
TEST(RfxImporter, PolygonModesAndLineWidthAreApplied) {
    const std::string gl = glEffect(
        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\"><RmRenderStateBlock NAME=\"S\">"
        "<RmState NAME=\"GL_PolyFrontMode\" STATE=\"27\" VALUE=\"3\"/><RmState NAME=\"GL_PolyBackMode\" STATE=\"28\" VALUE=\"2\"/>"
        "<RmState NAME=\"GL_LineWidth\" STATE=\"25\" VALUE=\"1082130432\"/></RmRenderStateBlock>\n" +
        std::string(kFragment) + "</RmGLPass>\n");
    Result<Workspace> outline = importRfxText(gl, "t.rfx", ".", {""});
    ASSERT_TRUE(outline) << formatAll(outline.diagnostics());
    ASSERT_EQ(outline->passes.size(), 1u);
    EXPECT_EQ(outline->passes[0].raster.frontMode, PolygonMode::Fill);
    EXPECT_EQ(outline->passes[0].raster.backMode, PolygonMode::Line);
    EXPECT_EQ(outline->passes[0].raster.lineWidth, 4.0f);  // 0x40800000
    EXPECT_EQ(outline->passes[0].raster.polygonModeWhere.line, 4);

    Result<Workspace> wire = importRfxText(d3dEffect(d3dStatePass(0, d3dState(8, "2"))), "t.rfx", ".", {""});
    ASSERT_TRUE(wire) << formatAll(wire.diagnostics());
    EXPECT_EQ(wire->passes[0].raster.frontMode, PolygonMode::Line);
    EXPECT_EQ(wire->passes[0].raster.backMode, PolygonMode::Line);
    EXPECT_NE(errorsOf(d3dEffect(d3dStatePass(0, d3dState(8, "4")))).find("VALUE 4 is not a D3DFILLMODE (it takes 1, 2, 3)"),
              std::string::npos);
    EXPECT_NE(errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\"><RmRenderStateBlock NAME=\"S\">"
                                "<RmState NAME=\"GL_LineWidth\" STATE=\"25\" VALUE=\"0.25\"/></RmRenderStateBlock>" +
                                std::string(kFragment) + "</RmGLPass>\n"))
                  .find("VALUE 0.25 is not a line width from 1 to 64 pixels"),
              std::string::npos);
}

TEST(RfxImporter, Direct3dSeparateAlphaBlendingCarriesOverWithTheOtherStates) {
    auto pass = d3dStatePass;
    auto state = [](int number, int value) { return d3dState(number, std::to_string(value)); };
    // P0: separate alpha on, alpha ONE, ONE. P1: colour SRCALPHA only; alpha keeps ONE, ONE.
    // P2: separate alpha off: alpha blends like colour again. P3: separate alpha on again: the
    // alpha states P0 set are still there (Direct3D kept them while they were not used).
    std::string text = d3dEffect(pass(0, state(27, 1) + state(206, 1) + state(207, 2) + state(208, 2)) + pass(1, state(19, 5)) +
                                 pass(2, state(206, 0)) + pass(3, state(206, 1)));
    Result<Workspace> p = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    const std::vector<Pass>& passes = p->passes;
    ASSERT_EQ(passes.size(), 4u);
    EXPECT_TRUE(passes[1].blend.enabled);
    EXPECT_EQ(passes[1].blend.srcColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(passes[1].blend.dstColor, BlendFactor::Zero);
    EXPECT_EQ(passes[1].blend.srcAlpha, BlendFactor::One);
    EXPECT_EQ(passes[1].blend.dstAlpha, BlendFactor::One);
    EXPECT_TRUE(passes[2].blend.enabled);
    EXPECT_EQ(passes[2].blend.srcAlpha, BlendFactor::SrcAlpha);
    EXPECT_EQ(passes[2].blend.dstAlpha, BlendFactor::Zero);
    EXPECT_EQ(passes[3].blend.srcAlpha, BlendFactor::One);
    EXPECT_EQ(passes[3].blend.dstAlpha, BlendFactor::One);
    EXPECT_EQ(passes[3].blend.srcColor, BlendFactor::SrcAlpha);
}

// Every D3D9 value RenderMonkey accepted maps or warns: SRCALPHASAT, the BOTH* factors (source
// and destination at once), floats written as decimal text, an anisotropic mip filter.
TEST(RfxImporter, Direct3dBlendFactorsAndDecimalStateValuesRenderMonkeyAccepted) {
    std::string text = d3dEffect(d3dStatePass(0, d3dState(27, "1") + d3dState(19, "11") + d3dState(20, "2") +
                                                     d3dState(195, "0.250000") + d3dState(7, "1.000000")) +
                                 d3dStatePass(1, d3dState(19, "12")) + d3dStatePass(2, d3dState(19, "13")) +
                                 d3dStatePass(3, d3dState(20, "12")));
    Result<Workspace> p = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
    const std::vector<Pass>& passes = p->passes;
    ASSERT_EQ(passes.size(), 4u);
    EXPECT_EQ(passes[0].blend.srcColor, BlendFactor::SrcAlphaSaturate);
    EXPECT_EQ(passes[0].blend.dstColor, BlendFactor::One);
    EXPECT_EQ(passes[0].blend.srcAlpha, BlendFactor::SrcAlphaSaturate);  // no separate alpha: like colour
    EXPECT_TRUE(passes[0].depth.test);
    EXPECT_EQ(passes[1].blend.srcColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(passes[1].blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(passes[2].blend.srcColor, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(passes[2].blend.dstColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(passes[3].blend.srcColor, BlendFactor::SrcAlpha);
    EXPECT_EQ(passes[3].blend.dstColor, BlendFactor::OneMinusSrcAlpha);
    const std::string warnings = formatAll(p.diagnostics());
    EXPECT_NE(warnings.find("render state D3DRS_195 = 0.25 has no equivalent"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("D3DBLEND_BOTHSRCALPHA is a source factor that sets the destination too"), std::string::npos)
        << warnings;

    // A whole-number state given a fraction, and text that is no number, are errors on the element.
    for (const char* bad : {"0.5", "1.0.0"}) {
        Result<Workspace> wrong = importRfxText(d3dEffect(d3dStatePass(0, d3dState(7, bad))), "t.rfx", ".", {""});
        EXPECT_FALSE(wrong.ok()) << bad;
        EXPECT_NE(formatAll(wrong.diagnostics()).find(std::string("attribute VALUE: '") + bad + "' is not a"),
                  std::string::npos)
            << formatAll(wrong.diagnostics());
    }

    // The sampler of d3d_hlsl.rfx with an anisotropic mip filter and a LOD bias written as text.
    std::string file = test::readText(rfxDir() / "d3d_hlsl.rfx");
    const std::string mip = "D3DSAMP_MIPFILTER\" API=\"D3D\" STATE=\"7\" VALUE=\"0\" USAGE=\"0\"/>";
    ASSERT_NE(file.find(mip), std::string::npos);
    file.replace(file.find(mip), mip.size(),
                 "D3DSAMP_MIPFILTER\" API=\"D3D\" STATE=\"7\" VALUE=\"3\" USAGE=\"0\"/><RmState NAME=\"D3DSAMP_MIPMAPLODBIAS\" API=\"D3D\" STATE=\"8\" "
                 "VALUE=\"-0.500000\" USAGE=\"0\"/>");
    Result<Workspace> sampled = importRfxText(file, "d3d_hlsl.rfx", rfxDir(), {""});
    ASSERT_TRUE(sampled.ok()) << formatAll(sampled.diagnostics());
    const std::string samplerWarnings = formatAll(sampled.diagnostics());
    EXPECT_NE(samplerWarnings.find("D3DTEXF_ANISOTROPIC as the mip filter is sampled as linear"), std::string::npos)
        << samplerWarnings;
    EXPECT_NE(samplerWarnings.find("D3DSAMP_MIPMAPLODBIAS = -0.5 has no equivalent"), std::string::npos) << samplerWarnings;
}

TEST(RfxImporter, ShadersKeepTheirRfxLinesAndDialect) {
    Workspace ws = imported("gl_legacy.rfx");
    const std::filesystem::path file = rfxDir() / "gl_legacy.rfx";
    const Pass& show = ws.passes[1];
    ASSERT_EQ(show.shaders.size(), 2u);
    EXPECT_EQ(show.shaders[0].stage, ShaderStage::Vertex);
    EXPECT_EQ(show.shaders[1].stage, ShaderStage::Fragment);
    for (const ShaderSource& s : show.shaders) EXPECT_EQ(s.dialect, ShaderDialect::GlslLegacy);
    // The CDATA opens on the RmShaderCode line: code line 1 is that line's remainder (empty).
    EXPECT_EQ(show.shaders[1].codeLine, lineOf(file, "<RmGLShader NAME=\"Fragment Program\""));
    EXPECT_EQ(show.shaders[1].code.substr(0, 26), "\nuniform sampler2D Scene;\n");
    // "Again" has no shaders: it runs the program of the pass before it.
    ASSERT_EQ(ws.passes[2].shaders.size(), 2u);
    EXPECT_EQ(ws.passes[2].shaders[1].code, show.shaders[1].code);
    EXPECT_EQ(ws.passes[2].shaders[1].codeLine, show.shaders[1].codeLine);
    // ...with the samplers and streams that program reads, as it names none of its own.
    ASSERT_EQ(ws.passes[2].samplers.size(), 1u);
    EXPECT_EQ(ws.passes[2].samplers[0].target, "Scene");
    EXPECT_EQ(ws.passes[2].streams.size(), show.streams.size());
}

// RenderMonkey 1.0 kept a shader's code in its CODE attribute and the constants in
// DECLARATION_BLOCK, compiled first: code line 1 is the element's line, the declarations before it.
TEST(RfxImporter, RenderMonkey10ShadersFromAttributesAndTheActiveEffectByName) {
    const std::filesystem::path file = rfxDir() / "rm10_attribute_code.rfx";
    Workspace ws = imported("rm10_attribute_code.rfx");
    EXPECT_EQ(allWarnings("rm10_attribute_code.rfx").find("ACTIVE_EFFECT"), std::string::npos)
        << allWarnings("rm10_attribute_code.rfx");
    ASSERT_EQ(ws.passes.size(), 1u);
    EXPECT_EQ(ws.passes[0].name, "Single Pass");
    ASSERT_EQ(ws.passes[0].shaders.size(), 2u);
    const ShaderSource& pixel = ws.passes[0].shaders[1];
    EXPECT_EQ(pixel.stage, ShaderStage::Fragment);
    EXPECT_EQ(pixel.code.rfind("float4 Color: register(c0);\nfloat Gain: register(c1);\nfloat4 ps_main()", 0), 0u) << pixel.code;
    EXPECT_EQ(pixel.codeLine, lineOf(file, "PIXEL_SHADER=\"TRUE\" DECLARATION_BLOCK=\"float4") - 2);
    EXPECT_EQ(ws.passes[0].shaders[0].code.substr(0, 28), "// Vertex shader entry point");
    EXPECT_EQ(ws.passes[0].shaders[0].codeLine, lineOf(file, "CODE=\"// Vertex shader entry point"));
    EXPECT_NE(errorsOf("<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"E\">\n<RmDirectXEffect NAME=\"E\" "
                       "API=\"D3D\">\n<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmHLSLShader NAME=\"S\" "
                       "PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"/>\n</RmPass>\n</RmDirectXEffect>\n"
                       "</RmEffectWorkspace>\n</RENDER_MONKEY>\n")
                  .find("t.rfx:5: error: <RmHLSLShader NAME=\"S\">: it has no <RmShaderCode> (nor a CODE attribute, where "
                        "RenderMonkey 1.0 kept the code)"),
              std::string::npos);
}

TEST(RfxImporter, SamplerStatesAndStreams) {
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

TEST(RfxImporter, VariablesOfEveryTypeWithScopesSemanticsAndRanges) {
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

TEST(RfxImporter, TexturesKeepFileNamesAsWritten) {
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

TEST(RfxImporter, GlSamplerStatesOfTextureVariables) {
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
    std::string at = "gl_legacy.rfx:" + std::to_string(line) + ": warning: <RmTextureObject NAME=\"Sky\">: ";
    EXPECT_NE(warnings.find(at + "minify and magnify filters differ"), std::string::npos) << warnings;
    EXPECT_EQ(sky.wrapR, Wrap::Clamp);  // GL_TextureWrapR 1 (GL_CLAMP), kept for volumes; a cube map ignores it
    EXPECT_EQ(warnings.find("R wrap"), std::string::npos) << warnings;
    // 1082130432 = 0x40800000 = 4.0f
    EXPECT_NE(warnings.find("sampler state GL_TextureMaxAnisotropyEXT = 4 has no equivalent"), std::string::npos) << warnings;
}

TEST(RfxImporter, RenderableTexturesTakeEveryD3dFormatNumber) {
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

TEST(RfxImporter, CameraBecomesTheOrbitThatSeesTheSame) {
    Workspace ws = imported("gl_legacy.rfx");
    // Position (3, 4, 0) looking at the origin: distance 5, yaw atan2(3, 0) = 90°, pitch asin(4/5).
    EXPECT_FLOAT_EQ(ws.camera.distance, 5.0f);
    EXPECT_NEAR(ws.camera.yawDegrees, 90.0f, 1e-4);
    EXPECT_NEAR(ws.camera.pitchDegrees, std::asin(0.8) * 180.0 / M_PI, 1e-4);
    EXPECT_FLOAT_EQ(ws.camera.fovYDegrees, 45.0f);
    EXPECT_FLOAT_EQ(ws.camera.nearPlane, 0.5f);
    EXPECT_FLOAT_EQ(ws.camera.farPlane, 50.0f);
}

// An ACTIVE_CAMERA naming none of the effect's RmCameras is a warning; with no RmCamera at all it
// names RenderMonkey's viewer camera ("Camera" in most files), which the import recovers or frames
// (RfxCameraFraming): no warning.
TEST(RfxImporter, ActiveCameraNamingNoCameraWarns) {
    auto warnings = [](const std::string& text) { return formatAll(importRfxText(text, "t.rfx", ".", {}).diagnostics()); };
    const std::string pass = "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n</RmGLPass>\n";
    std::string none = glEffect(pass);
    none.replace(none.find("API=\"OpenGL\">"), 14, "API=\"OpenGL\" ACTIVE_CAMERA=\"Camera\">");
    EXPECT_EQ(warnings(none).find("ACTIVE_CAMERA"), std::string::npos) << warnings(none);
    std::string other = glEffect("<RmCamera NAME=\"Side\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"3\"/>\n" + pass);
    other.replace(other.find("API=\"OpenGL\">"), 14, "API=\"OpenGL\" ACTIVE_CAMERA=\"Main\">");
    EXPECT_NE(warnings(other).find("ACTIVE_CAMERA 'Main' names no <RmCamera> of the effect; using the first one, 'Side'"),
              std::string::npos)
        << warnings(other);
    EXPECT_EQ(allWarnings("gl_legacy.rfx").find("ACTIVE_CAMERA"), std::string::npos);
}

TEST(RfxImporter, ModelOrientationOtherThanZeroWarns) {
    std::string text = glEffect("<RmModelData NAME=\"M\" FILE_NAME=\"m.obj\" ORIENTATION=\"1\"/>\n"
                                "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n" + std::string(kFragment) + "\n</RmGLPass>\n");
    std::string all = formatAll(importRfxText(text, "t.rfx", ".", {}).diagnostics());
    EXPECT_NE(all.find("t.rfx:4: warning: <RmModelData NAME=\"M\">: ORIENTATION 1 is not applied"), std::string::npos) << all;
    EXPECT_EQ(allWarnings("gl_legacy.rfx").find("ORIENTATION"), std::string::npos);
}

// RenderMonkey's stream maps are shared by every pass that names one: a channel a pass's shaders
// do not read is normal there (a screen-aligned quad's pass ignores the normals), not a warning.
TEST(RfxImporter, SharedStreamChannelsAPassDoesNotReadAreNotWarnedAbout) {
    Result<Workspace> loaded = loadWorkspace(rfxDir() / "d3d_hlsl.rfx");  // BINORMAL2: no shader reads it
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    for (const Pass& pass : loaded->passes)
        for (const VertexStream& stream : pass.streams) EXPECT_TRUE(stream.shared);
    EXPECT_EQ(formatAll(loaded.diagnostics()).find("do not read"), std::string::npos) << formatAll(loaded.diagnostics());
}

TEST(RfxImporter, EffectChosenByDottedPathOrName) {
    for (const char* name : {"Tests.Group.Other", "Group.Other", "Other"}) {
        Workspace ws = imported("gl_legacy.rfx", name);
        EXPECT_EQ(ws.name, "Tests.Group.Other") << name;
        ASSERT_EQ(ws.passes.size(), 1u);
        EXPECT_EQ(ws.passes[0].draw.file, "");  // no model reference
        // Shadowed: the workspace's 1.0 (the sibling effect's 0.0 is not visible here).
        EXPECT_FLOAT_EQ(variable(ws, "Shadowed").value.asFloat(), 1.0f);
        EXPECT_NE(ws.findTexture("Noise"), nullptr);
    }
    EXPECT_EQ(imported("gl_legacy.rfx").findTexture("Noise"), nullptr);  // the sibling's declarations are not visible
    std::string errors = formatAll(importRfxFile(rfxDir() / "gl_legacy.rfx", {"Nope"}).diagnostics());
    EXPECT_NE(errors.find("error: --effect Nope: no effect 'Nope'; it has: 'Tests.Group.Legacy' (OpenGL, active), "
                          "'Tests.Group.Other' (OpenGL)"),
              std::string::npos)
        << errors;
}

TEST(RfxImporter, GlesEffectFeedsNamedAttributes) {
    Workspace ws = imported("gles.rfx");
    EXPECT_EQ(ws.profile, GlProfile::Core);
    ASSERT_EQ(ws.passes.size(), 1u);
    const Pass& p = ws.passes[0];
    for (const ShaderSource& s : p.shaders) EXPECT_EQ(s.dialect, ShaderDialect::GlslEs100);
    ASSERT_EQ(p.streams.size(), 3u);  // the blend-weights channel is left out, with a warning
    EXPECT_EQ(p.streams[0].attribute, "a_position");
    EXPECT_EQ(p.streams[1].attribute, "a_uv");
    EXPECT_EQ(p.streams[2].usage, VertexUsage::Color);
    EXPECT_EQ(p.streams[2].attribute, "a_color");
    EXPECT_TRUE(p.blend.enabled);
    EXPECT_EQ(p.blend.srcColor, BlendFactor::One);
    EXPECT_EQ(p.blend.dstColor, BlendFactor::One);
    EXPECT_FALSE(p.depth.test);
    ASSERT_TRUE(p.clear.color.has_value());
    expectColor(*p.clear.color, {32 / 255.0f, 32 / 255.0f, 32 / 255.0f, 1.0f});  // 0xFF202020
    int line = lineOf(rfxDir() / "gles.rfx", "NAME=\"Weights\"");
    EXPECT_NE(allWarnings("gles.rfx").find("gles.rfx:" + std::to_string(line) + ": warning: <RmStreamChannel NAME=\"Weights\">: USAGE 1"),
              std::string::npos);
}

TEST(RfxImporter, Direct3dEffectWithHlslStatesAndADisabledAssemblyPass) {
    Workspace ws = imported("d3d_hlsl.rfx");
    EXPECT_EQ(ws.profile, GlProfile::Core);
    ASSERT_EQ(ws.passes.size(), 3u);  // the disabled assembly pass is kept, translated to HLSL
    const Pass& fill = ws.passes[0];
    ASSERT_EQ(fill.shaders.size(), 2u);
    EXPECT_EQ(fill.shaders[0].dialect, ShaderDialect::Hlsl);
    EXPECT_EQ(fill.shaders[0].entryPoint, "vs_main");
    EXPECT_EQ(fill.shaders[0].profile, "vs_2_0");
    EXPECT_EQ(fill.shaders[1].entryPoint, "ps_main");
    EXPECT_EQ(fill.shaders[1].profile, "ps_2_0");
    EXPECT_EQ(fill.target, "Buffer");
    EXPECT_FALSE(fill.depth.test);
    EXPECT_FALSE(fill.depth.write);
    EXPECT_EQ(fill.depth.func, CompareFunc::NotEqual);  // D3DCMP 6
    EXPECT_EQ(fill.raster.cull, CullFace::None);
    EXPECT_EQ(fill.blend.srcColor, BlendFactor::SrcAlpha);          // D3DBLEND 5
    EXPECT_EQ(fill.blend.dstColor, BlendFactor::OneMinusSrcAlpha);  // 6
    EXPECT_EQ(fill.blend.colorOp, BlendOp::ReverseSubtract);        // 3
    // No separate alpha blending: alpha blends like colour.
    EXPECT_EQ(fill.blend.srcAlpha, BlendFactor::SrcAlpha);
    EXPECT_EQ(fill.blend.dstAlpha, BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(fill.blend.alphaOp, BlendOp::ReverseSubtract);
    ASSERT_EQ(fill.streams.size(), 3u);
    EXPECT_EQ(fill.streams[2].usage, VertexUsage::Binormal);
    EXPECT_EQ(fill.streams[2].usageIndex, 2);

    const Pass& twice = ws.passes[1];
    EXPECT_EQ(twice.raster.cull, CullFace::Front);  // D3DCULL_CW: clockwise faces culled, which
    EXPECT_FALSE(twice.raster.frontCounterClockwise);  // are Direct3D's front faces
    EXPECT_EQ(twice.blend.srcAlpha, BlendFactor::One);
    EXPECT_EQ(twice.blend.dstAlpha, BlendFactor::Zero);
    EXPECT_EQ(twice.blend.alphaOp, BlendOp::Max);
    expectColor(twice.blend.constant, {0.0f, 1.0f, 0.0f, 1.0f});  // 0xFF00FF00
    ASSERT_EQ(twice.samplers.size(), 1u);
    const Sampler& s = twice.samplers[0];
    EXPECT_EQ(s.uniform, "BufferSampler");
    EXPECT_EQ(s.target, "Buffer");
    EXPECT_EQ(s.wrapS, Wrap::Clamp);   // D3DTADDRESS_CLAMP 3
    EXPECT_EQ(s.wrapT, Wrap::Border);  // 4
    expectColor(s.border, {1.0f, 0.0f, 0.0f, 1.0f});  // 0xFFFF0000
    EXPECT_EQ(s.filter, Filter::Nearest);
    EXPECT_EQ(s.mipmap, MipmapMode::None);

    std::string warnings = allWarnings("d3d_hlsl.rfx");
    const Pass& legacy = ws.passes[2];
    EXPECT_FALSE(legacy.enabled);
    ASSERT_EQ(legacy.shaders.size(), 1u);
    EXPECT_EQ(legacy.shaders[0].dialect, ShaderDialect::Hlsl);
    EXPECT_EQ(legacy.shaders[0].entryPoint, "rm_asm_main");
    EXPECT_EQ(legacy.shaders[0].profile, "ps_1_1");  // what it was written for
    int line = lineOf(rfxDir() / "d3d_hlsl.rfx", "<RmShader NAME=");
    EXPECT_NE(warnings.find("d3d_hlsl.rfx:" + std::to_string(line) +
                            ": warning: <RmShader NAME=\"Pixel Shader\">: Direct3D assembly (ps_1_1) translated to HLSL"),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("d3d_hlsl.rfx:" + std::to_string(lineOf(rfxDir() / "d3d_hlsl.rfx", "mov r0, c0")) +
                            ": warning: <RmShader NAME=\"Pixel Shader\">: c0 is neither defined (def) nor set"),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("D3DRS_DEPTHBIAS = 0.5 has no equivalent"), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find("D3DRS_FILLMODE"), std::string::npos) << warnings;  // 3, solid: applied
}

// Fixed-function fog states (terrain_fog.rfx: linear table fog from 1 to 1000 in white) become the
// pass's fog and carry over to the passes after it; vertex fog is warned about (with a vertex
// shader it is the shader's FOG output).
TEST(RfxImporter, FogStatesBecomeThePasssFixedFunctionFog) {
    const std::string fog = d3dState(28, "1") + d3dState(36, "1.000000") + d3dState(37, "1000.000000") +
                            d3dState(34, "16777215") + d3dState(38, "2.000000") + d3dState(35, "3");
    Result<Workspace> ws = importRfxText(d3dEffect(d3dStatePass(0, fog) + d3dStatePass(1, "")), "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    for (const Pass& pass : ws->passes) {
        SCOPED_TRACE(pass.name);
        EXPECT_TRUE(pass.fog.applies());
        EXPECT_EQ(pass.fog.mode, FogMode::Linear);
        EXPECT_EQ(pass.fog.start, 1.0f);
        EXPECT_EQ(pass.fog.end, 1000.0f);
        EXPECT_EQ(pass.fog.density, 2.0f);
        EXPECT_EQ(pass.fog.color, glm::vec3(1.0f));
    }
    EXPECT_EQ(formatAll(ws.diagnostics()).find("FOG"), std::string::npos) << formatAll(ws.diagnostics());

    // Vertex fog set in the first pass and carried into the second: one warning.
    Result<Workspace> vertex =
        importRfxText(d3dEffect(d3dStatePass(0, d3dState(28, "1") + d3dState(140, "3")) + d3dStatePass(1, "")), "t.rfx", ".", {""});
    ASSERT_TRUE(vertex) << formatAll(vertex.diagnostics());
    EXPECT_FALSE(vertex->passes[0].fog.applies());
    const std::string warnings = formatAll(vertex.diagnostics());
    const std::string message = "vertex fog (D3DRS_FOGVERTEXMODE) takes the vertex shader's FOG output";
    ASSERT_NE(warnings.find(message), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find(message, warnings.find(message) + 1), std::string::npos) << warnings;
    EXPECT_NE(errorsOf(d3dEffect(d3dStatePass(0, d3dState(35, "4")))).find("VALUE 4 is not a D3DFOGMODE (it takes 0, 1, 2, 3)"),
              std::string::npos);
}

// D3DRS_ZENABLE 0 turns depth buffering off: no test and no write, though ZWRITEENABLE stays TRUE
// (a sky sphere drawn with ZENABLE 0 must not hide what is drawn after it). The write state comes
// back with the next pass that turns ZENABLE on.
TEST(RfxImporter, ZEnableOffWritesNoDepth) {
    Result<Workspace> ws = importRfxText(
        d3dEffect(d3dStatePass(0, d3dState(7, "0")) + d3dStatePass(1, "") + d3dStatePass(2, d3dState(7, "1"))), "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    ASSERT_EQ(ws->passes.size(), 3u);
    for (int i : {0, 1}) {
        EXPECT_FALSE(ws->passes[i].depth.test) << i;
        EXPECT_FALSE(ws->passes[i].depth.write) << i;
    }
    EXPECT_TRUE(ws->passes[2].depth.test);
    EXPECT_TRUE(ws->passes[2].depth.write);  // ZWRITEENABLE was never changed from TRUE
}

// D3DRS_ALPHATESTENABLE, ALPHAFUNC and ALPHAREF (a byte) make the pass's alpha test, carried
// over like the other states.
TEST(RfxImporter, AlphaTestStatesBecomeThePasssAlphaTest) {
    Result<Workspace> ws = importRfxText(
        d3dEffect(d3dStatePass(0, d3dState(15, "1") + d3dState(25, "7") + d3dState(24, "128")) + d3dStatePass(1, "")), "t.rfx",
        ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    for (const Pass& pass : ws->passes) {
        EXPECT_TRUE(pass.alphaTest.enabled);
        EXPECT_EQ(pass.alphaTest.func, CompareFunc::GreaterEqual);
        EXPECT_EQ(pass.alphaTest.ref, 128.0f / 255.0f);
    }
    EXPECT_EQ(formatAll(ws.diagnostics()).find("ALPHA"), std::string::npos) << formatAll(ws.diagnostics());
    EXPECT_NE(errorsOf(d3dEffect(d3dStatePass(0, d3dState(24, "300")))).find("VALUE 300 is not an alpha reference (0 to 255)"),
              std::string::npos);
}

// RenderMonkey 1.5 and before passed matrices in OpenGL's layout (its HLSL wrote
// mul(view_proj_matrix, Pos)); 1.6 and later as D3DX does (mul(Input.Position, matViewProjection)).
// The version that saved the file decides; assembly always reads rows (m4x4).
TEST(RfxImporter, HlslMatrixOrderFollowsTheVersionThatSavedTheFile) {
    for (const auto& [version, order] : {std::pair{"RenderMonkey 1.5", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.0", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.62", HlslMatrixOrder::RowVector},
                                         std::pair{"RenderMonkey 1.71", HlslMatrixOrder::RowVector},
                                         std::pair{"RenderMonkey 2.0", HlslMatrixOrder::RowVector}}) {
        SCOPED_TRACE(version);
        std::string text = d3dEffect(d3dStatePass(0, ""));
        text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + std::string(version) + "\" ");
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        ASSERT_EQ(ws->passes[0].shaders.size(), 1u);
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, order);
        EXPECT_EQ(formatAll(ws.diagnostics()).find("XML_VERSION"), std::string::npos) << formatAll(ws.diagnostics());
    }
    for (const std::string& attribute : {std::string(), std::string("XML_VERSION=\"RenderMonkey\" ")}) {
        std::string text = d3dEffect(d3dStatePass(0, ""));
        text.replace(text.find("ACTIVE_EFFECT"), 0, attribute);
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
        const std::string warnings = formatAll(ws.diagnostics());
        EXPECT_NE(warnings.find("t.rfx:2: warning: <RmEffectWorkspace NAME=\"W\">: XML_VERSION " +
                                std::string(attribute.empty() ? "missing" : "\"RenderMonkey\"") +
                                ": HLSL semantic matrices are passed as RenderMonkey 1.6 and later did, for mul(v, M)"),
                  std::string::npos)
            << warnings;
    }
    Workspace ws = imported("d3d_hlsl.rfx");  // RenderMonkey 1.71, with a disabled assembly pass
    EXPECT_EQ(ws.passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(ws.passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
}

// A file whose HLSL was written for the other order than its version implies (gaxlin's
// LensFlare_10: saved by 1.71, mul(g_matViewProj, v)) is given the order asked for
// (rmfx render --rfx-matrices); assembly still reads rows, and a version that cannot be read is
// not warned about, since it decides nothing.
TEST(RfxImporter, TheHlslMatrixOrderAskedForOverridesTheVersion) {
    for (const auto& [version, asked] : {std::pair{"RenderMonkey 1.71", HlslMatrixOrder::ColumnVector},
                                         std::pair{"RenderMonkey 1.5", HlslMatrixOrder::RowVector},
                                         std::pair{"", HlslMatrixOrder::ColumnVector}}) {
        SCOPED_TRACE(version);
        std::string text = d3dEffect(d3dStatePass(0, ""));
        if (*version) text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + std::string(version) + "\" ");
        Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {"", asked});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, asked);
        EXPECT_EQ(formatAll(ws.diagnostics()).find("XML_VERSION"), std::string::npos) << formatAll(ws.diagnostics());
    }
    Result<Workspace> ws = importRfxFile(rfxDir() / "d3d_hlsl.rfx", {"", HlslMatrixOrder::ColumnVector});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    ws = importRfxFile(rfxDir() / "d3d_hlsl.rfx", {"", HlslMatrixOrder::RowVector});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector) << "assembly";
}

// A Direct3D effect saved by `version` whose vertex shader (`code` from line 13 of the file)
// multiplies with `code`, the semantic matrices Mvp (ViewProjection), MvpT
// (ViewProjectionTranspose) and Wld (World) and the stored matrix S visible.
std::string matrixOrderEffect(const std::string& version, const std::string& code) {
    std::string values;
    for (int i = 0; i < 16; ++i) values += " VALUE_" + std::to_string(i) + "=\"" + (i % 5 == 0 ? "1" : "0") + "\"";
    std::string text = d3dEffect(
        "<RmMatrixVariable NAME=\"Mvp\" VARIABLE_SEMANTIC=\"ViewProjection\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"MvpT\" VARIABLE_SEMANTIC=\"ViewProjectionTranspose\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"S\" VARIABLE_SEMANTIC=\"\"" + values + "/>\n"
        "<RmMatrixVariable NAME=\"Wld\" VARIABLE_SEMANTIC=\"World\"" + values + "/>\n"
        "<RmPass NAME=\"P\" PASS_INDEX=\"0\"><RmHLSLShader NAME=\"VS\" PIXEL_SHADER=\"FALSE\" TARGET=\"vs_2_0\" "
        "ENTRY_POINT=\"main\"><RmShaderConstant NAME=\"Mvp\"/><RmShaderConstant NAME=\"MvpT\"/><RmShaderConstant NAME=\"S\"/>"
        "<RmShaderConstant NAME=\"Wld\"/><RmShaderCode><![CDATA[\nfloat4x4 Mvp : register(c0);\nfloat4x4 MvpT;\nfloat4x4 S; float4x4 Wld;\n"
        "float4 main(float4 p : POSITION) : POSITION {\n" + code + "\n}]]></RmShaderCode></RmHLSLShader></RmPass>\n");
    if (!version.empty()) text.replace(text.find("ACTIVE_EFFECT"), 0, "XML_VERSION=\"" + version + "\" ");
    return text;
}

// Which way round the HLSL multiplies the semantic matrices decides their order where it says one
// (LensFlare_10, saved by 1.71, writes mul(g_matViewProj, v)); a warning names the line that goes
// against the version. Where the code says both, or nothing, the version decides.
TEST(RfxImporter, TheHlslMatrixOrderFollowsWhatTheCodeMultiplies) {
    struct Case {
        const char* version;
        const char* code;  // from line 13 of the file
        HlslMatrixOrder expected;
        const char* warning;  // empty: none
    };
    const Case cases[] = {
        {"RenderMonkey 1.71", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:2: warning: <RmEffectWorkspace NAME=\"W\">: t.rfx:13 multiplies mul(Mvp, p) (1 such in the effect), where "
         "RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" passed its semantic matrices for mul(v, M): they are passed for "
         "mul(M, v), as the code asks (--rfx-matrices to choose)"},
        {"RenderMonkey 1.71", "return mul(float4(p.xyz, 1), (Mvp));", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.5", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector, ""},
        {"RenderMonkey 1.5", "float4 q = mul(p, Mvp);\nreturn mul(q, Mvp);", HlslMatrixOrder::RowVector,
         "t.rfx:13 multiplies mul(p, Mvp) (2 such in the effect), where RenderMonkey of XML_VERSION \"RenderMonkey 1.5\" passed "
         "its semantic matrices for mul(M, v): they are passed for mul(v, M)"},
        // A transposed semantic, or transpose(), counts the other way round.
        {"RenderMonkey 1.71", "return mul(MvpT, p);", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.71", "return mul(transpose(Mvp), p);", HlslMatrixOrder::RowVector, ""},
        {"RenderMonkey 1.5", "return mul(p, transpose(Mvp));", HlslMatrixOrder::ColumnVector, ""},
        // A product of matrices whose order of transforms is unknown (World and a stored or local
        // matrix, a transposed semantic), a stored matrix alone, no variable, or something on the
        // other side that is not known to be a vector says nothing.
        {"RenderMonkey 1.5", "float4x4 W = S;\nreturn mul(mul(Wld, S), p) + mul(Mvp, MvpT) + mul(p, S) + mul(p, Mvp[0]) + mul(W, Wld) + "
         "mul(2 * p, Mvp) + mul(unknown, Mvp) + mul(MvpT, S);",
         HlslMatrixOrder::ColumnVector, ""},
        {"RenderMonkey 1.71", "float4x4 W = S;\nreturn mul(Wld, W) + mul((float4x4) S, Wld) + mul(Mvp, MvpT) + mul(S, W);", HlslMatrixOrder::RowVector, ""},
        // Nothing comes after the projection: a matrix ending in it stands last whatever the other
        // (simpleCubeMapReflection-3, saved by 1.71: mul(view_proj_matrix, matWorld), matWorld stored).
        {"RenderMonkey 1.71", "float4x4 m = mul(Mvp, S);\nreturn mul(m, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:13 multiplies mul(Mvp, S) (2 such in the effect)"},
        {"RenderMonkey 1.5", "float4x4 W = S;\nreturn mul(p, mul(W, Mvp));", HlslMatrixOrder::RowVector,
         "t.rfx:14 multiplies mul(W, Mvp) (1 such in the effect)"},
        // Two semantic matrices: the one applied later on the left is M·v's order (skyBox_11,
        // saved by 1.71, writes m = mul(matViewProjection, matWorld); mul(m, Pos)).
        {"RenderMonkey 1.71", "float4x4 m = mul(Mvp, Wld);\nreturn mul(m, p);", HlslMatrixOrder::ColumnVector,
         "t.rfx:13 multiplies mul(Mvp, Wld) (2 such in the effect)"},
        {"RenderMonkey 1.5", "float4x4 m = mul(Wld, Mvp);\nreturn mul(p, m);", HlslMatrixOrder::RowVector,
         "t.rfx:13 multiplies mul(Wld, Mvp) (2 such in the effect)"},
        // A local computed from a semantic matrix counts as that matrix beside a vector: the product
        // says v·M's order, the position M·v's (rainBow_transp-1, saved by 1.5), and the version decides.
        {"RenderMonkey 1.5", "float4x4 mtr = mul(S, Mvp);\nreturn mul(mtr, p);", HlslMatrixOrder::ColumnVector,
         "both ways round (mul(mtr, p) at t.rfx:14, 1 such; mul(S, Mvp) at t.rfx:13, 1 such): they are passed for mul(M, v)"},
        {"RenderMonkey 1.71", "float4 q = mul(Mvp, mul(S, p)) + mul(mul(p, S), Mvp);\nreturn mul(Mvp, p) + mul(p.xyzw, Mvp);",
         HlslMatrixOrder::RowVector,
         "both ways round (mul(Mvp, p) at t.rfx:14, 1 such; mul(p.xyzw, Mvp) at t.rfx:14, 1 such): they are passed for mul(v, M), "
         "as RenderMonkey of XML_VERSION \"RenderMonkey 1.71\" did"},
        // Without a version the code decides, unwarned; with neither, the later versions' order, warned.
        {"", "return mul(Mvp, p);", HlslMatrixOrder::ColumnVector, ""},
        {"", "return p;", HlslMatrixOrder::RowVector, "XML_VERSION missing: HLSL semantic matrices are passed as RenderMonkey 1.6"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.version) + ": " + c.code);
        Result<Workspace> ws = importRfxText(matrixOrderEffect(c.version, c.code), "t.rfx", ".", {""});
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        ASSERT_EQ(ws->passes.size(), 1u);
        ASSERT_EQ(ws->passes[0].shaders.size(), 1u);
        EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, c.expected);
        const std::string said = formatAll(ws.diagnostics());
        if (*c.warning) {
            EXPECT_NE(said.find(c.warning), std::string::npos) << said;
        } else {
            EXPECT_EQ(said.find("mul("), std::string::npos) << said;
        }
        if (std::string(c.warning).find("XML_VERSION missing") == std::string::npos) {
            EXPECT_EQ(said.find("XML_VERSION missing"), std::string::npos) << said;
        }
    }
    // A matrix the pass declares itself counts too.
    std::string passLevel = matrixOrderEffect("RenderMonkey 1.71", "return mul(Own, p);");
    std::string own16;
    for (int i = 0; i < 16; ++i) own16 += " VALUE_" + std::to_string(i) + "=\"" + (i % 5 == 0 ? "1" : "0") + "\"";
    passLevel.replace(passLevel.find("<RmHLSLShader"), 0,
                      "<RmMatrixVariable NAME=\"Own\" VARIABLE_SEMANTIC=\"WorldViewProjection\"" + own16 + "/>");
    passLevel.replace(passLevel.find("float4x4 S;"), 0, "float4x4 Own;\n");
    Result<Workspace> own = importRfxText(passLevel, "t.rfx", ".", {""});
    ASSERT_TRUE(own) << formatAll(own.diagnostics());
    EXPECT_EQ(own->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector) << formatAll(own.diagnostics());
    // What --rfx-matrices asks for overrides the code too.
    Result<Workspace> asked = importRfxText(matrixOrderEffect("RenderMonkey 1.71", "return mul(Mvp, p);"), "t.rfx", ".",
                                            {"", HlslMatrixOrder::RowVector});
    ASSERT_TRUE(asked) << formatAll(asked.diagnostics());
    EXPECT_EQ(asked->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(formatAll(asked.diagnostics()).find("mul("), std::string::npos) << formatAll(asked.diagnostics());
}

// A file upgraded from 1.5 keeps shaders writing mul(M, v) beside new ones writing mul(v, M)
// (atMOS_PassMethod_03: the planet's passes one way, the ring's the other): each shader whose own
// code says one order gets it, unwarned; a shader that says nothing gets the effect's.
TEST(RfxImporter, EachShaderGetsTheMatrixOrderItsOwnCodeMultiplies) {
    std::string text = matrixOrderEffect("RenderMonkey 1.71", "return mul(Mvp, p);");
    const std::string pass = text.substr(text.find("<RmPass"), text.find("</RmPass>") + 9 - text.find("<RmPass"));
    std::string ring = pass, quiet = pass;
    ring.replace(ring.find("PASS_INDEX=\"0\""), 14, "PASS_INDEX=\"1\"");
    ring.replace(ring.find("return mul(Mvp, p);"), 19, "return mul(p, Mvp);");
    quiet.replace(quiet.find("PASS_INDEX=\"0\""), 14, "PASS_INDEX=\"2\"");
    quiet.replace(quiet.find("return mul(Mvp, p);"), 19, "return p;");
    text.insert(text.find("</RmPass>") + 9, "\n" + ring + "\n" + quiet);
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    ASSERT_EQ(ws->passes.size(), 3u);
    EXPECT_EQ(ws->passes[0].shaders[0].matrixOrder, HlslMatrixOrder::ColumnVector);
    EXPECT_EQ(ws->passes[1].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);
    EXPECT_EQ(ws->passes[2].shaders[0].matrixOrder, HlslMatrixOrder::RowVector);  // the 1.71 version's
    EXPECT_EQ(formatAll(ws.diagnostics()).find("mul("), std::string::npos) << formatAll(ws.diagnostics());

    // A shader that says both ways round (a product for v·M, a local through it for M·v) gets
    // mul(M, v) when compiled with COMPILER_FLAGS 32 (rainBow_transp-1's copy saved by 1.71), else
    // the version's order.
    for (const auto& [flags, expected] : {std::pair{"32", HlslMatrixOrder::ColumnVector}, std::pair{"0", HlslMatrixOrder::RowVector}}) {
        std::string both = matrixOrderEffect("RenderMonkey 1.71", "float4x4 mtr = mul(S, Mvp);\nreturn mul(mtr, p);");
        both.replace(both.find("ENTRY_POINT=\"main\""), 0, "COMPILER_FLAGS=\"" + std::string(flags) + "\" ");
        Result<Workspace> flagged = importRfxText(both, "t.rfx", ".", {""});
        ASSERT_TRUE(flagged) << formatAll(flagged.diagnostics());
        EXPECT_EQ(flagged->passes[0].shaders[0].matrixOrder, expected) << flags;
    }
}

// The test file written in LensFlare_10's way: both shaders of its pass get the order its vertex
// shader's mul(g_matViewProj, v) asks for, with a warning naming that line.
TEST(RfxImporter, AFileWrittenForTheOtherMatrixOrderIsReadByItsCode) {
    Result<Workspace> ws = importRfxFile(rfxDir() / "d3d_matrix_order.rfx", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    ASSERT_EQ(ws->passes.size(), 1u);
    ASSERT_EQ(ws->passes[0].shaders.size(), 2u);
    for (const ShaderSource& s : ws->passes[0].shaders) EXPECT_EQ(s.matrixOrder, HlslMatrixOrder::ColumnVector);
    const std::string said = formatAll(ws.diagnostics());
    EXPECT_NE(said.find("d3d_matrix_order.rfx:34 multiplies mul(g_matViewProj, float4(corner, 1)) (1 such in the effect)"), std::string::npos)
        << said;
}

TEST(RfxImporter, AssemblyShaderInAnEnabledPassIsAnError) {
    std::string errors = errorsOf(glEffect(
        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
        "<RmShader NAME=\"Asm\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[ps.1.1]]></RmShaderCode></RmShader>\n"
        "</RmGLPass>\n"));
    EXPECT_NE(errors.find("t.rfx:5: warning: <RmShader NAME=\"Asm\">: an assembly shader"), std::string::npos) << errors;
    EXPECT_NE(errors.find("t.rfx:4: error: <pass \"P\">: the effect cannot run: its pixel shader <RmShader NAME=\"Asm\"> "
                          "(line 5) is assembly"),
              std::string::npos)
        << errors;
}

TEST(RfxImporter, BadInputsAreErrorsWithFileAndLine) {
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
TEST(RfxImporter, TruncatedAndDamagedFilesNeverCrash) {
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

TEST(RfxImporter, DoctypeWithItsInternalSubsetKeepsLineNumbers) {
    // gl_legacy.rfx opens with a DTD whose quoted '>' would end tinyxml2's DOCTYPE early.
    Workspace ws = imported("gl_legacy.rfx");
    EXPECT_EQ(ws.findVariable("Tint")->where.line, lineOf(rfxDir() / "gl_legacy.rfx", "NAME=\"Tint\""));
}

TEST(RfxImporter, LoaderDispatchesOnTheExtensionInAnyCase) {
    std::filesystem::path dir = test::binaryDir() / "rfx-loader-test";
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(rfxDir() / "gles.rfx", dir / "Upper.RFX", std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(rfxDir() / "quad.obj", dir / "quad.obj", std::filesystem::copy_options::overwrite_existing);
    ValidationOptions structureOnly;
    structureOnly.compileShaders = false;
    Result<Workspace> loaded = loadWorkspace(dir / "Upper.RFX", structureOnly);
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    Result<Workspace> wrong = loadWorkspace(dir / "Upper.RFX", structureOnly, {"Nope", {}, {}});
    EXPECT_FALSE(wrong.ok());
    Result<Workspace> xml = loadWorkspace(test::sourceDir() / "effects" / "shader_1.xml", structureOnly, {"Some.Effect", {}, {}});
    EXPECT_FALSE(xml.ok());
    EXPECT_NE(formatAll(xml.diagnostics()).find("--effect chooses an effect of a RenderMonkey .rfx file"), std::string::npos);
}

TEST(RfxImporter, EditorSavesIntoAnRfxAreRefused) {
    auto saved = saveVariableValues(rfxDir() / "gles.rfx", {{"Gain", Value::ofFloat(0.25f)}});
    ASSERT_FALSE(saved.ok());
    EXPECT_NE(saved.error().find("saving tweaked values into a RenderMonkey .rfx file is not supported"), std::string::npos);
}

TEST(RfxImporter, ListNamesEveryEffectWithItsApiAndActiveFlag) {
    Result<std::vector<RfxEffectSummary>> list = listRfxEffects(rfxDir() / "gl_legacy.rfx");
    ASSERT_TRUE(list.ok()) << formatAll(list.diagnostics());
    ASSERT_EQ(list->size(), 2u);
    EXPECT_EQ((*list)[0].path, "Tests.Group.Legacy");
    EXPECT_EQ((*list)[0].api, "OpenGL");
    EXPECT_TRUE((*list)[0].active);
    EXPECT_EQ((*list)[1].path, "Tests.Group.Other");
    EXPECT_FALSE((*list)[1].active);
}

}  // namespace
}  // namespace rmfx

namespace rmfx {
namespace {

// Direct3D assembly shaders: translated to HLSL, problems at their .rfx line (body from line 4).
TEST(RfxImporter, AssemblyShadersBecomeHlslAndTheirErrorsNameTheRfxLine) {
    const std::string vs = "<RmShader NAME=\"VS\" PIXEL_SHADER=\"FALSE\"><RmShaderCode><![CDATA[\nvs.1.1\n"
                           "dcl_position v0\nm4x4 oPos, v0, c0\nmov oT0, c4]]></RmShaderCode>\n"
                           "<RmShaderConstant NAME=\"M\" REGISTER=\"0\"/></RmShader>\n";
    const std::string matrix = "<RmMatrixVariable NAME=\"M\" VARIABLE_SEMANTIC=\"\" VALUE_0=\"1\" VALUE_1=\"0\" VALUE_2=\"0\" "
                               "VALUE_3=\"0\" VALUE_4=\"0\" VALUE_5=\"1\" VALUE_6=\"0\" VALUE_7=\"0\" VALUE_8=\"0\" VALUE_9=\"0\" "
                               "VALUE_10=\"1\" VALUE_11=\"0\" VALUE_12=\"0\" VALUE_13=\"0\" VALUE_14=\"0\" VALUE_15=\"1\"/>\n";
    auto pass = [&](bool enabled, const std::string& ps) {
        return matrix + "<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"" + (enabled ? "TRUE" : "FALSE") + "\">\n" + vs +
               "<RmShader NAME=\"PS\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[\nps.1.1\n" + ps +
               "]]></RmShaderCode></RmShader>\n</RmPass>\n";
    };
    Result<Workspace> ok = importRfxText(d3dEffect(pass(true, "mov r0, t0")), "t.rfx", ".", {""});
    ASSERT_TRUE(ok.ok()) << formatAll(ok.diagnostics());
    ASSERT_EQ(ok->passes.size(), 1u);
    ASSERT_EQ(ok->passes[0].shaders.size(), 2u);
    const ShaderSource& v = ok->passes[0].shaders[0];
    EXPECT_EQ(v.dialect, ShaderDialect::Hlsl);
    EXPECT_EQ(v.entryPoint, "rm_asm_main");
    EXPECT_EQ(v.profile, "vs_1_1");  // what it was written for
    EXPECT_EQ(v.codeLine, 6);  // the CDATA's first line: generated line N is the code's line N
    EXPECT_NE(v.code.find("float4x4 M;"), std::string::npos) << v.code;
    const std::string warnings = formatAll(ok.diagnostics());
    EXPECT_NE(warnings.find("t.rfx:6: warning: <RmShader NAME=\"VS\">: Direct3D assembly (vs_1_1) translated to HLSL"),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("t.rfx:10: warning: <RmShader NAME=\"VS\">: c4 is neither defined"), std::string::npos) << warnings;

    std::string errors = errorsOf(d3dEffect(pass(true, "mov r0, t0\ntexm3x2depth t1, t0")));
    EXPECT_NE(errors.find("t.rfx:15: error: <RmShader NAME=\"PS\">: the instruction 'texm3x2depth' is not supported"), std::string::npos)
        << errors;
    EXPECT_NE(errors.find("error: <pass \"P\">: the effect cannot run: its pixel shader <RmShader NAME=\"PS\"> (line 12) "
                          "could not be translated from assembly"),
              std::string::npos)
        << errors;

    // In a disabled pass the same problems are warnings, and the pass is left out (leaving none).
    Result<Workspace> disabled = importRfxText(d3dEffect(pass(false, "mov r0, t0\nfoo r0")), "t.rfx", ".", {""});
    EXPECT_EQ(formatAll(disabled.diagnostics()).find("error: <RmShader"), std::string::npos) << formatAll(disabled.diagnostics());
    EXPECT_NE(formatAll(disabled.diagnostics()).find("t.rfx:15: warning: <RmShader NAME=\"PS\">: unknown instruction 'foo'"),
              std::string::npos)
        << formatAll(disabled.diagnostics());
}

// Texture stage states (USAGE="TEXTURE_STATE") share their numbers with the sampler states but are
// not sampler states: D3DTSS_COLOROP (1) is no D3DSAMP_ADDRESSU, and the bump matrix (7-10) reaches
// texbem instead of the mip filter.
TEST(RfxImporter, TextureStageStatesAreNotSamplerStatesAndFeedTexbem) {
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

}  // namespace
}  // namespace rmfx

namespace rmfx {

// ORIGIN 0 (every public file's) is how rmfx reads images; another value is named in a warning.
TEST(RfxImporter, TextureOriginOtherThanZeroIsAWarning) {
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
    EXPECT_NE(formatAll(one.diagnostics()).find("t.rfx:4: warning: <Rm2DTextureVariable NAME=\"T\">: ORIGIN 1 is not applied"),
              std::string::npos)
        << formatAll(one.diagnostics());
}

// A pass may declare its own texture, renderable texture and model (RenderMonkey's assembly fur
// does), after the texture objects and shaders that use them.
TEST(RfxImporter, TexturesTargetsAndModelsDeclaredInsideAPassAreThePasss) {
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

// RmCameraReference: a pass names a camera of the effect; the active one is the camera the viewer
// moves, any other a fixed camera of its own; one the effect lacks is a warning.
TEST(RfxImporter, CameraReferencesPickAPassesCamera) {
    auto camera = [](const std::string& name, const std::string& z, const std::string& upX) {
        return "<RmCamera NAME=\"" + name + "\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"" + z +
               "\" LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"" + upX +
               "\" UP_VECTOR_Y=\"1\" UP_VECTOR_Z=\"0\" FOV=\"45\" NEAR_CLIP_PLANE=\"1\" FAR_CLIP_PLANE=\"100\"/>\n";
    };
    auto pass = [](int index, const std::string& reference) {
        return "<RmGLPass NAME=\"P" + std::to_string(index) + "\" PASS_INDEX=\"" + std::to_string(index) + "\" ENABLED=\"TRUE\">" +
               (reference.empty() ? "" : "<RmCameraReference NAME=\"" + reference + "\"/>") + std::string(kFragment) +
               "</RmGLPass>\n";
    };
    const std::string text = "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
                             "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\" ACTIVE_CAMERA=\"Viewer\">\n" +
                             camera("Viewer", "10", "0") + camera("Light", "20", "1") + pass(0, "Viewer") + pass(1, "Light") +
                             pass(2, "") + pass(3, "Nowhere") + "</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    Result<Workspace> ws = importRfxText(text, "t.rfx", ".", {""});
    ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
    EXPECT_FLOAT_EQ(ws->camera.distance, 10.0f);
    ASSERT_EQ(ws->cameras.size(), 1u);
    EXPECT_EQ(ws->cameras[0].name, "Light");
    EXPECT_FLOAT_EQ(ws->cameras[0].settings.distance, 20.0f);
    EXPECT_NEAR(ws->cameras[0].settings.rollDegrees, 45.0f, 1e-4);  // up (1, 1, 0) looking down -Z
    ASSERT_EQ(ws->passes.size(), 4u);
    EXPECT_EQ(ws->passes[0].camera, "");  // the active one
    EXPECT_EQ(ws->passes[1].camera, "Light");
    EXPECT_EQ(ws->passes[2].camera, "");
    EXPECT_EQ(ws->passes[3].camera, "");
    EXPECT_NE(formatAll(ws.diagnostics())
                  .find("t.rfx:9: warning: <RmCameraReference NAME=\"Nowhere\">: the effect has no <RmCamera NAME=\"Nowhere\">"),
              std::string::npos)
        << formatAll(ws.diagnostics());
}

// RenderMonkey's viewer stored FOVs past 180 degrees (its zoom went there) and D3DX's
// PerspectiveFovLH used them as they were: y scale cot(FOV / 2) < 0, so FOV 200 shows what FOV
// 160 shows, turned 180 degrees. Checked against that formula in double for a point in view.
TEST(RfxImporter, AFovPast180DegreesTurnsThePictureAsD3dxDid) {
    auto effect = [](const std::string& fov) {
        return "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n<RmDirectXEffect NAME=\"E\" API=\"D3D\">\n"
               "<RmCamera NAME=\"C\" CAMERA_POSITION_X=\"0\" CAMERA_POSITION_Y=\"0\" CAMERA_POSITION_Z=\"-10\" "
               "LOOK_AT_VECTOR_X=\"0\" LOOK_AT_VECTOR_Y=\"0\" LOOK_AT_VECTOR_Z=\"0\" UP_VECTOR_X=\"0\" UP_VECTOR_Y=\"1\" "
               "UP_VECTOR_Z=\"0\" FOV=\"" + fov + "\" NEAR_CLIP_PLANE=\"1\" FAR_CLIP_PLANE=\"100\"/>\n" +
               d3dStatePass(0, "") + "</RmDirectXEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    };
    Result<Workspace> wide = importRfxText(effect("200"), "t.rfx", ".", {""});
    ASSERT_TRUE(wide) << formatAll(wide.diagnostics());
    EXPECT_FLOAT_EQ(wide->camera.fovYDegrees, 200.0f);
    const double aspect = 1.5, pi = std::acos(-1.0);
    const glm::mat4 projection = OrbitCamera(wide->camera).projection(static_cast<float>(aspect));
    const double yScale = 1.0 / std::tan(200.0 / 2.0 * pi / 180.0);  // D3DX: cot(fovY / 2)
    EXPECT_LT(yScale, 0.0);
    EXPECT_NEAR(projection[1][1], yScale, 1e-6 * std::abs(yScale));
    EXPECT_NEAR(projection[0][0], yScale / aspect, 1e-6 * std::abs(yScale));
    // The same point through FOV 160: x and y negated.
    Result<Workspace> narrow = importRfxText(effect("160"), "t.rfx", ".", {""});
    ASSERT_TRUE(narrow) << formatAll(narrow.diagnostics());
    const glm::vec4 point(1.0f, 0.5f, 0.0f, 1.0f);
    auto ndc = [&](const Workspace& ws) {
        const OrbitCamera camera(ws.camera);
        const glm::vec4 clip = camera.projection(static_cast<float>(aspect)) * camera.view() * point;
        return glm::vec2(clip) / clip.w;
    };
    EXPECT_NEAR(ndc(*wide).x, -ndc(*narrow).x, 1e-5);
    EXPECT_NEAR(ndc(*wide).y, -ndc(*narrow).y, 1e-5);
    EXPECT_GT(std::abs(ndc(*narrow).x), 0.01f);

    for (const std::string bad : {"180", "360", "0", "-20"}) {
        Result<Workspace> refused = importRfxText(effect(bad), "t.rfx", ".", {""});
        EXPECT_FALSE(refused) << bad;
        EXPECT_NE(formatAll(refused.diagnostics()).find("is not an angle in (0, 360) degrees other than 180"), std::string::npos)
            << formatAll(refused.diagnostics());
    }
}

}  // namespace rmfx
