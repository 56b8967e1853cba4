// The RenderMonkey importer: the effect chosen from a file, its passes in run order and their shaders
// (GLSL, GLSL ES, HLSL, Direct3D assembly), on the .rfx files written for these tests (tests/rfx/):
// every expected number below is worked out by hand from the file's text.

#include "frontend/rfx/RfxImporter.h"

#include <gtest/gtest.h>

#include "frontend/workspace/VariableValueWriter.h"
#include "RfxImporterTestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

TEST(RfxImporterEffects, GlEffectPassesRunInPassIndexOrderWithTheirTargetsAndClears) {
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

TEST(RfxImporterEffects, ShadersKeepTheirRfxLinesAndDialect) {
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
TEST(RfxImporterEffects, RenderMonkey10ShadersFromAttributesAndTheActiveEffectByName) {
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
    const std::string noCode = errorsOf(
        "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"E\">\n<RmDirectXEffect NAME=\"E\" "
        "API=\"D3D\">\n<RmPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n<RmHLSLShader NAME=\"S\" "
        "PIXEL_SHADER=\"TRUE\" TARGET=\"ps_2_0\" ENTRY_POINT=\"main\"/>\n</RmPass>\n</RmDirectXEffect>\n"
        "</RmEffectWorkspace>\n</RENDER_MONKEY>\n");
    EXPECT_TRUE(test::hasLine(noCode,
                              "t.rfx:5: error: <RmHLSLShader NAME=\"S\">: it has no <RmShaderCode> (nor a CODE attribute, "
                              "where RenderMonkey 1.0 kept the code)"))
        << noCode;
}

TEST(RfxImporterEffects, EffectChosenByDottedPathOrName) {
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
    EXPECT_TRUE(
        test::hasLine(errors, (rfxDir() / "gl_legacy.rfx").string() +
                                  ": error: --effect Nope: no effect 'Nope'; it has: 'Tests.Group.Legacy' (OpenGL, active), "
                                  "'Tests.Group.Other' (OpenGL)"))
        << errors;
}

TEST(RfxImporterEffects, GlesEffectFeedsNamedAttributes) {
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
    EXPECT_TRUE(test::hasLine(allWarnings("gles.rfx"),
                              (rfxDir() / "gles.rfx").string() + ":" + std::to_string(line) +
                                  ": warning: <RmStreamChannel NAME=\"Weights\">: USAGE 1 (blend weights, indices, point "
                                  "size…) has no vertex data in rmfx's meshes; the channel is left out"))
        << allWarnings("gles.rfx");
}

TEST(RfxImporterEffects, Direct3dEffectWithHlslStatesAndADisabledAssemblyPass) {
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
    const std::string file = (rfxDir() / "d3d_hlsl.rfx").string();
    EXPECT_TRUE(
        test::hasLine(warnings, file + ":" + std::to_string(line) +
                                    ": warning: <RmShader NAME=\"Pixel Shader\">: Direct3D assembly (ps_1_1) translated to "
                                    "HLSL for rmfx's HLSL path"))
        << warnings;
    EXPECT_TRUE(
        test::hasLine(warnings, file + ":" + std::to_string(lineOf(file, "mov r0, c0")) +
                                    ": warning: <RmShader NAME=\"Pixel Shader\">: c0 is neither defined (def) nor set by an "
                                    "RmShaderConstant: Direct3D left it unset, so it reads 0"))
        << warnings;
    EXPECT_TRUE(
        test::hasLine(warnings, file + ":" + std::to_string(lineOf(file, "D3DRS_DEPTHBIAS")) +
                                    ": warning: <RmState NAME=\"D3DRS_DEPTHBIAS\">: render state D3DRS_DEPTHBIAS = 0.5 has no "
                                    "equivalent in rmfx's pass model; ignored"))
        << warnings;
    EXPECT_EQ(warnings.find("D3DRS_FILLMODE"), std::string::npos) << warnings;  // 3, solid: applied
}

TEST(RfxImporterEffects, AssemblyShaderInAnEnabledPassIsAnError) {
    std::string errors = errorsOf(glEffect(
        "<RmGLPass NAME=\"P\" PASS_INDEX=\"0\" ENABLED=\"TRUE\">\n"
        "<RmShader NAME=\"Asm\" PIXEL_SHADER=\"TRUE\"><RmShaderCode><![CDATA[ps.1.1]]></RmShaderCode></RmShader>\n"
        "</RmGLPass>\n"));
    EXPECT_EQ(errors,
              test::lines({"t.rfx:5: warning: <RmShader NAME=\"Asm\">: an assembly shader: rmfx compiles only HLSL and GLSL, "
                           "so this pass cannot run",
                           "t.rfx:4: error: <pass \"P\">: the effect cannot run: its pixel shader <RmShader NAME=\"Asm\"> "
                           "(line 5) is assembly (disable the pass to run the rest)"}));
}

// Direct3D assembly shaders: translated to HLSL, problems at their .rfx line (body from line 4).
TEST(RfxImporterEffects, AssemblyShadersBecomeHlslAndTheirErrorsNameTheRfxLine) {
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
    EXPECT_TRUE(
        test::hasLine(warnings,
                      "t.rfx:6: warning: <RmShader NAME=\"VS\">: Direct3D assembly (vs_1_1) translated to HLSL for rmfx's "
                      "HLSL path"))
        << warnings;
    EXPECT_TRUE(test::hasLine(warnings,
                              "t.rfx:10: warning: <RmShader NAME=\"VS\">: c4 is neither defined (def) nor set by an "
                              "RmShaderConstant: Direct3D left it unset, so it reads 0"))
        << warnings;

    std::string errors = errorsOf(d3dEffect(pass(true, "mov r0, t0\ntexm3x2depth t1, t0")));
    EXPECT_TRUE(test::hasLine(errors,
                              "t.rfx:15: error: <RmShader NAME=\"PS\">: the instruction 'texm3x2depth' is not supported by "
                              "rmfx's assembly translation"))
        << errors;
    EXPECT_TRUE(test::hasLine(errors,
                              "t.rfx:5: error: <pass \"P\">: the effect cannot run: its pixel shader <RmShader NAME=\"PS\"> "
                              "(line 12) could not be translated from assembly (disable the pass to run the rest)"))
        << errors;

    // In a disabled pass the same problems are warnings, and the pass is left out (leaving none).
    Result<Workspace> disabled = importRfxText(d3dEffect(pass(false, "mov r0, t0\nfoo r0")), "t.rfx", ".", {""});
    EXPECT_EQ(formatAll(disabled.diagnostics()).find("error: <RmShader"), std::string::npos) << formatAll(disabled.diagnostics());
    EXPECT_TRUE(
        test::hasLine(formatAll(disabled.diagnostics()), "t.rfx:15: warning: <RmShader NAME=\"PS\">: unknown instruction 'foo'"))
        << formatAll(disabled.diagnostics());
}

TEST(RfxImporterEffects, DoctypeWithItsInternalSubsetKeepsLineNumbers) {
    // gl_legacy.rfx opens with a DTD whose quoted '>' would end tinyxml2's DOCTYPE early.
    Workspace ws = imported("gl_legacy.rfx");
    EXPECT_EQ(ws.findVariable("Tint")->where.line, lineOf(rfxDir() / "gl_legacy.rfx", "NAME=\"Tint\""));
}

TEST(RfxImporterEffects, LoaderDispatchesOnTheExtensionInAnyCase) {
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
    EXPECT_EQ(formatAll(xml.diagnostics()),
              test::lines({(test::sourceDir() / "effects" / "shader_1.xml").string() +
                           ": error: --effect Some.Effect: --effect chooses an effect of a RenderMonkey .rfx file; this is an "
                           "rmfx workspace (use --effects to choose its <effect> groups)"}));
}

TEST(RfxImporterEffects, EditorSavesIntoAnRfxAreRefused) {
    auto saved = saveVariableValues(rfxDir() / "gles.rfx", {{"Gain", Value::ofFloat(0.25f)}});
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.error(), (rfxDir() / "gles.rfx").string() +
                                 ": error: saving tweaked values into a RenderMonkey .rfx file is not supported (rmfx never "
                                 "rewrites .rfx files); pass the values with --set NAME=VALUE, or note them down");
}

TEST(RfxImporterEffects, ListNamesEveryEffectWithItsApiAndActiveFlag) {
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
