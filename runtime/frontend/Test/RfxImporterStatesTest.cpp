// The RenderMonkey importer's render states: OpenGL and Direct3D state blocks become each pass's
// blend, depth, raster, fog and alpha test, carried over in run order as RenderMonkey did.

#include "frontend/rfx/RfxImporter.h"

#include <gtest/gtest.h>

#include "RfxImporterTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::rfx_importer;

// What d3dEffect's text, which names no XML_VERSION, is warned about first.
const std::string kNoVersion =
    "t.rfx:2: warning: <RmEffectWorkspace NAME=\"W\">: XML_VERSION missing: HLSL semantic matrices are "
    "passed as RenderMonkey 1.6 and later did, for mul(v, M)";

TEST(RfxImporterStates, GlRenderStatesMapToBlendDepthAndRaster) {
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

TEST(RfxImporterStates, RenderStatesCarryOverInRunOrderFromThePassesThatRun) {
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

// Silhouette outlines: back faces drawn as lines (RenderMonkey's 1 GL_POINT, 2 GL_LINE, 3 GL_FILL)
// of a width; Direct3D's D3DRS_FILLMODE (1 point, 2 wireframe, 3 solid) sets both faces.
TEST(RfxImporterStates, PolygonModesAndLineWidthAreApplied) {
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
    EXPECT_EQ(
        errorsOf(d3dEffect(d3dStatePass(0, d3dState(8, "4")))),
        test::lines({kNoVersion, "t.rfx:4: error: <RmState NAME=\"D3DRS_8\">: VALUE 4 is not a D3DFILLMODE (it takes 1, 2, 3)"}));
    EXPECT_EQ(
        errorsOf(glEffect("<RmGLPass NAME=\"P\" PASS_INDEX=\"0\"><RmRenderStateBlock NAME=\"S\">"
                          "<RmState NAME=\"GL_LineWidth\" STATE=\"25\" VALUE=\"0.25\"/></RmRenderStateBlock>" +
                          std::string(kFragment) + "</RmGLPass>\n")),
        test::lines({"t.rfx:4: error: <RmState NAME=\"GL_LineWidth\">: VALUE 0.25 is not a line width from 1 to 64 pixels"}));
}

TEST(RfxImporterStates, Direct3dSeparateAlphaBlendingCarriesOverWithTheOtherStates) {
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
TEST(RfxImporterStates, Direct3dBlendFactorsAndDecimalStateValuesRenderMonkeyAccepted) {
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
    EXPECT_TRUE(test::hasLine(warnings,
                              "t.rfx:4: warning: <RmState NAME=\"D3DRS_195\">: render state D3DRS_195 = 0.25 has no "
                              "equivalent in rmfx's pass model; ignored"))
        << warnings;
    EXPECT_TRUE(test::hasLine(warnings,
                              "t.rfx:7: warning: <RmState NAME=\"D3DRS_20\">: D3DBLEND_BOTHSRCALPHA is a source factor "
                              "that sets the destination too; read as such here"))
        << warnings;

    // A whole-number state given a fraction, and text that is no number, are errors on the element.
    for (const auto& [bad, why] :
         {std::pair{"0.5", "is not a whole number, and this state takes one"}, std::pair{"1.0.0", "is not a number"}}) {
        Result<Workspace> wrong = importRfxText(d3dEffect(d3dStatePass(0, d3dState(7, bad))), "t.rfx", ".", {""});
        EXPECT_FALSE(wrong.ok()) << bad;
        EXPECT_TRUE(
            test::hasLine(formatAll(wrong.diagnostics()),
                          "t.rfx:4: error: <RmState NAME=\"D3DRS_7\">: attribute VALUE: '" + std::string(bad) + "' " + why))
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
    const std::string at =
        "d3d_hlsl.rfx:" + std::to_string(lineOf(rfxDir() / "d3d_hlsl.rfx", "D3DSAMP_MIPFILTER")) + ": warning: ";
    EXPECT_TRUE(
        test::hasLine(samplerWarnings, at + "<RmState NAME=\"D3DSAMP_MIPFILTER\">: D3DTEXF_ANISOTROPIC as the mip filter is "
                                            "sampled as linear (rmfx samplers have no anisotropy)"))
        << samplerWarnings;
    EXPECT_TRUE(
        test::hasLine(samplerWarnings, at + "<RmState NAME=\"D3DSAMP_MIPMAPLODBIAS\">: sampler state D3DSAMP_MIPMAPLODBIAS = "
                                            "-0.5 has no equivalent in rmfx's sampler model; ignored"))
        << samplerWarnings;
}

// Fixed-function fog states (terrain_fog.rfx: linear table fog from 1 to 1000 in white) become the
// pass's fog and carry over to the passes after it; vertex fog is warned about (with a vertex
// shader it is the shader's FOG output).
TEST(RfxImporterStates, FogStatesBecomeThePasssFixedFunctionFog) {
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
    EXPECT_EQ(errorsOf(d3dEffect(d3dStatePass(0, d3dState(35, "4")))),
              test::lines({kNoVersion,
                           "t.rfx:4: error: <RmState NAME=\"D3DRS_35\">: VALUE 4 is not a D3DFOGMODE (it takes 0, 1, 2, 3)"}));
}

// D3DRS_ZENABLE 0 turns depth buffering off: no test and no write, though ZWRITEENABLE stays TRUE
// (a sky sphere drawn with ZENABLE 0 must not hide what is drawn after it). The write state comes
// back with the next pass that turns ZENABLE on.
TEST(RfxImporterStates, ZEnableOffWritesNoDepth) {
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
TEST(RfxImporterStates, AlphaTestStatesBecomeThePasssAlphaTest) {
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
    EXPECT_EQ(
        errorsOf(d3dEffect(d3dStatePass(0, d3dState(24, "300")))),
        test::lines({kNoVersion, "t.rfx:4: error: <RmState NAME=\"D3DRS_24\">: VALUE 300 is not an alpha reference (0 to 255)"}));
}

}  // namespace
}  // namespace rmfx
