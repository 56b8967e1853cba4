// ReshadeParser's techniques: their annotations, passes named or not, every pass state ReShade
// knows with its value checked, compute passes, and the entry points and render targets resolved.
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

}  // namespace

TEST(ReshadeParserTechniques, AnnotationsAndEveryPassState) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, test::shaderPair() +
                 lines({"texture A { Format = RGBA16F; }; texture B { Format = RGBA8; };",
                        "technique Bloom < ui_label = \"Bloom\"; ui_tooltip = \"Glow\"; enabled = true; toggle = 0x20;",
                        "  timeout = 1000; hidden = false; >", "{", "  pass Blur {", "    VertexShader = VS; PixelShader = PS;",
                        "    RenderTarget = A; RenderTarget1 = B; ClearRenderTargets = true; GenerateMipMaps = false;",
                        "    SRGBWriteEnable = true; BlendEnable = true; BlendEnable1 = false; BlendOp = REVSUBTRACT;",
                        "    BlendOpAlpha = max; SrcBlend = SRCALPHA; DestBlend = INVSRCALPHA; SrcBlendAlpha = ZERO;",
                        "    DestBlendAlpha = DESTCOLOR; DestBlend2 = INVDESTALPHA; ColorWriteMask = 0x7; RenderTargetWriteMask3 = 1 << 2;",
                        "    StencilEnable = true; StencilReadMask = 0x1FF; StencilWriteMask = 0x0F; StencilFunc = NOTEQUAL;",
                        "    StencilRef = 3; StencilPassOp = REPLACE; StencilFail = INCRSAT; StencilDepthFailOp = DECR;",
                        "    PrimitiveTopology = LINESTRIP; VertexCount = 4;", "  }",
                        "  pass { VertexShader = VS; PixelShader = PS; PrimitiveType = POINTLIST; StencilZFail = INVERT; }", "}"}));
    EXPECT_EQ(parse.problems(), Lines{});
    ASSERT_EQ(parse.effect.techniques.size(), 1u);
    const ReshadeTechnique& t = parse.effect.techniques[0];
    EXPECT_EQ(t.name, "Bloom");
    EXPECT_EQ(t.where.line, 4);
    Lines annotations;
    for (const ReshadeAnnotation& a : t.annotations) annotations.push_back(a.name + "=" + a.value.describe());
    EXPECT_EQ(annotations, (Lines{"ui_label=\"Bloom\"", "ui_tooltip=\"Glow\"", "enabled=true", "toggle=32", "timeout=1000",
                                  "hidden=false"}));
    ASSERT_EQ(t.passes.size(), 2u);
    const ReshadePass& p = t.passes[0];
    EXPECT_EQ(p.name, "Blur");
    EXPECT_EQ(p.where.line, 7);
    EXPECT_EQ(p.vertexShader, "VS");
    EXPECT_EQ(p.pixelShader, "PS");
    EXPECT_EQ(p.renderTargets[0], "A");
    EXPECT_EQ(p.renderTargets[1], "B");
    EXPECT_EQ(p.renderTargets[2], "");
    EXPECT_TRUE(p.clearRenderTargets);
    EXPECT_FALSE(p.generateMipMaps);
    EXPECT_TRUE(p.srgbWriteEnable);
    EXPECT_EQ(p.blendEnable, (std::array<bool, 8>{true, false, true, true, true, true, true, true}));
    EXPECT_EQ(p.blendOp[5], ReshadeBlendOp::RevSubtract);
    EXPECT_EQ(p.blendOpAlpha[0], ReshadeBlendOp::Max);
    EXPECT_EQ(p.srcBlend[0], ReshadeBlendFactor::SrcAlpha);
    EXPECT_EQ(p.destBlend[0], ReshadeBlendFactor::InvSrcAlpha);
    EXPECT_EQ(p.destBlend[2], ReshadeBlendFactor::InvDestAlpha);
    EXPECT_EQ(p.srcBlendAlpha[7], ReshadeBlendFactor::Zero);
    EXPECT_EQ(p.destBlendAlpha[0], ReshadeBlendFactor::DestColor);
    EXPECT_EQ(p.colorWriteMask, (std::array<uint8_t, 8>{7, 7, 7, 4, 7, 7, 7, 7}));
    EXPECT_TRUE(p.stencilEnable);
    EXPECT_EQ(p.stencilReadMask, 0xFF);
    EXPECT_EQ(p.stencilWriteMask, 0x0F);
    EXPECT_EQ(p.stencilFunc, ReshadeCompareFunc::NotEqual);
    EXPECT_EQ(p.stencilRef, 3u);
    EXPECT_EQ(p.stencilPass, ReshadeStencilOp::Replace);
    EXPECT_EQ(p.stencilFail, ReshadeStencilOp::IncrSat);
    EXPECT_EQ(p.stencilDepthFail, ReshadeStencilOp::Decr);
    EXPECT_EQ(p.topology, ReshadePrimitiveTopology::LineStrip);
    EXPECT_EQ(p.vertexCount, 4u);
    ASSERT_EQ(p.states.size(), 28u);
    EXPECT_EQ(p.states[9].name, "BlendOp");
    EXPECT_EQ(p.states[9].value, "REVSUBTRACT");
    EXPECT_EQ(p.states[9].where.line, 10);
    EXPECT_EQ(p.states[17].value, "1 << 2");
    const ReshadePass& q = t.passes[1];
    EXPECT_EQ(q.name, "");
    EXPECT_EQ(q.topology, ReshadePrimitiveTopology::PointList);
    EXPECT_EQ(q.stencilDepthFail, ReshadeStencilOp::Invert);
    EXPECT_EQ(q.vertexCount, 3u);  // the default
    EXPECT_EQ(q.srcBlend[0], ReshadeBlendFactor::One);
    EXPECT_EQ(q.colorWriteMask[0], 0xF);
}

TEST(ReshadeParserTechniques, ComputePassesAndNamespacedEntryPoints) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"texture T { Width = 64; Height = 64; Format = R32F; };", "storage S { Texture = T; };",
                    "namespace Fx {", "  void CS(uint3 id : SV_DispatchThreadID) { }",
                    "  technique Compute { pass { ComputeShader = CS<8, 8>; DispatchSizeX = 64 / 8; DispatchSizeY = 8; } }", "}",
                    "technique Deep { pass One { ComputeShader = Fx::CS<4, 2, 1 + 1>; DispatchSizeX = 1; DispatchSizeY = 2;",
                    "  DispatchSizeZ = 3; } }"}));
    EXPECT_EQ(parse.problems(), Lines{});
    ASSERT_EQ(parse.effect.techniques.size(), 2u);
    const ReshadePass& a = parse.effect.techniques[0].passes[0];
    EXPECT_EQ(a.computeShader, "Fx::CS");
    EXPECT_EQ(a.threadGroupSize, (std::array<int, 3>{8, 8, 1}));
    EXPECT_EQ(a.dispatchSize, (std::array<int, 3>{8, 8, 1}));
    const ReshadePass& b = parse.effect.techniques[1].passes[0];
    EXPECT_EQ(b.computeShader, "Fx::CS");
    EXPECT_EQ(b.threadGroupSize, (std::array<int, 3>{4, 2, 2}));
    EXPECT_EQ(b.dispatchSize, (std::array<int, 3>{1, 2, 3}));
}

TEST(ReshadeParserTechniques, BadStatesAreErrorsThatNameThePass) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, test::shaderPair() +
                 lines({"texture T { };", "sampler Smp { Texture = T; };", "technique Bloom {", "  pass {",
                        "    VertexShader = VS; PixelShader = PS;", "    SrcBlend = ADD;", "    BlendOp = 7;",
                        "    PrimitiveTopology = QUADS;", "    Shininess = 3;", "    RenderTarget = Smp;",
                        "    PixelShader = Missing;", "    RenderTarget9 = T;", "  }", "  pass Second { VertexShader = VS; }",
                        "  pass Third { ComputeShader = PS<0, 1>; }", "  pass Fourth { ComputeShader = PS; }", "}"}));
    EXPECT_EQ(parse.problems(),
              (Lines{"main.fx:8: error: pass 1 of technique Bloom: 'ADD' is not a blend factor for SrcBlend (expected ZERO, ONE, "
                     "SRCCOLOR, INVSRCCOLOR, SRCALPHA, INVSRCALPHA, DESTALPHA, INVDESTALPHA, DESTCOLOR, INVDESTCOLOR)",
                     "main.fx:9: error: pass 1 of technique Bloom: '7' is not a blend operation for BlendOp (expected ADD, "
                     "SUBTRACT, REVSUBTRACT, MIN, MAX)",
                     "main.fx:10: error: pass 1 of technique Bloom: 'QUADS' is not a primitive topology for PrimitiveTopology "
                     "(expected POINTLIST, LINELIST, LINESTRIP, TRIANGLELIST, TRIANGLESTRIP)",
                     "main.fx:11: error: pass 1 of technique Bloom: unknown pass state 'Shininess'",
                     "main.fx:12: error: pass 1 of technique Bloom: 'Smp' is a sampler, not a texture",
                     "main.fx:13: error: pass 1 of technique Bloom: PixelShader: undeclared identifier 'Missing', expected a "
                     "function",
                     "main.fx:14: error: pass 1 of technique Bloom: unknown pass state 'RenderTarget9'",
                     "main.fx:16: error: pass Second of technique Bloom: the pass has no PixelShader",
                     "main.fx:17: error: pass Third of technique Bloom: ComputeShader: a thread group size must be a positive "
                     "constant",
                     "main.fx:18: error: pass Fourth of technique Bloom: a compute pass needs DispatchSizeX and DispatchSizeY"}));
    // What was valid is kept
    ASSERT_EQ(parse.effect.techniques.size(), 1u);
    ASSERT_EQ(parse.effect.techniques[0].passes.size(), 4u);
    EXPECT_EQ(parse.effect.techniques[0].passes[0].pixelShader, "PS");
    EXPECT_EQ(parse.effect.techniques[0].passes[3].computeShader, "PS");
}

}  // namespace rmfx
