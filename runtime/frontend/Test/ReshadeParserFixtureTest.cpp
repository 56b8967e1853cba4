// ReshadePreprocessor and ReshadeParser together over a small effect written as ReShade's community
// writes them (Test/reshade/ParserEffect.fx and its ReShade.fxh-like header ParserCommon.fxh): a
// blur at half size through PostProcessVS, a combo uniform, samplers with states, and a compute
// pass writing a storage.
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;

std::string place(const SourceLocation& where) {
    return std::filesystem::path(where.file).filename().string() + ":" + std::to_string(where.line);
}

}  // namespace

TEST(ReshadeParserFixture, TwoTechniqueEffectWithAHeader) {
    const std::filesystem::path folder = test::sourceDir() / "runtime" / "frontend" / "Test" / "reshade";
    test::ReshadeRun pre;
    ReshadeInput input;
    input.file = folder / "ParserEffect.fx";
    pre.out = preprocessReshade(input, pre.diagnostics);
    const ReshadeEffect effect = parseReshadeEffect(pre.out, pre.diagnostics);
    EXPECT_EQ(pre.problems(folder.string()), Lines{});

    ASSERT_EQ(effect.uniforms.size(), 3u);
    const ReshadeUniform& mode = effect.uniforms[0];
    EXPECT_EQ(mode.name, "BlurMode");
    EXPECT_EQ(mode.type.base, ReshadeBaseType::Int);
    EXPECT_EQ(place(mode.where), "ParserEffect.fx:4");
    EXPECT_EQ(findAnnotation(mode.annotations, "ui_type")->value.text, "combo");
    EXPECT_EQ(findAnnotation(mode.annotations, "ui_items")->value.text, std::string("Box\0Gaussian\0", 13));
    EXPECT_EQ(place(findAnnotation(mode.annotations, "ui_label")->where), "ParserEffect.fx:7");
    EXPECT_EQ(mode.initializer->describe(), "1");
    EXPECT_EQ(effect.uniforms[1].initializer->describe(), "0.8");
    EXPECT_EQ(findAnnotation(effect.uniforms[1].annotations, "ui_category")->value.text, "Bloom");
    EXPECT_EQ(findAnnotation(effect.uniforms[2].annotations, "source")->value.text, "timer");

    ASSERT_EQ(effect.textures.size(), 4u);
    EXPECT_EQ(effect.textures[0].name, "ReShade::BackBufferTex");
    EXPECT_EQ(effect.textures[0].semantic, "COLOR");
    EXPECT_EQ(place(effect.textures[0].where), "ParserCommon.fxh:13");
    EXPECT_EQ(effect.textures[1].semantic, "DEPTH");
    const ReshadeTexture& half = effect.textures[2];
    EXPECT_EQ(half.name, "HalfTex");
    EXPECT_EQ(half.width, 960);
    EXPECT_EQ(half.height, 540);
    EXPECT_EQ(half.format, ReshadeTextureFormat::RGBA16F);
    EXPECT_EQ(place(half.where), "ParserEffect.fx:13");
    EXPECT_EQ(effect.textures[3].format, ReshadeTextureFormat::R32F);

    ASSERT_EQ(effect.samplers.size(), 3u);
    EXPECT_EQ(effect.samplers[0].name, "ReShade::BackBuffer");
    EXPECT_EQ(effect.samplers[0].texture, "ReShade::BackBufferTex");
    const ReshadeSampler& halfSampler = effect.samplers[2];
    EXPECT_EQ(halfSampler.texture, "HalfTex");
    EXPECT_EQ(halfSampler.address[0], ReshadeAddressMode::Mirror);
    EXPECT_EQ(halfSampler.address[1], ReshadeAddressMode::Mirror);
    EXPECT_EQ(halfSampler.address[2], ReshadeAddressMode::Clamp);
    EXPECT_EQ(halfSampler.magFilter, ReshadeFilter::Linear);
    EXPECT_EQ(halfSampler.minFilter, ReshadeFilter::Point);
    ASSERT_EQ(effect.storages.size(), 1u);
    EXPECT_EQ(effect.storages[0].texture, "HistTex");

    ASSERT_EQ(effect.variables.size(), 3u);
    EXPECT_EQ(effect.variables[0].name, "ReShade::PixelSize");
    ASSERT_TRUE(effect.variables[0].value.has_value());
    EXPECT_NEAR(effect.variables[0].value->at(0), 1.0 / 1920, 1e-12);
    EXPECT_NEAR(effect.variables[0].value->at(1), 1.0 / 1080, 1e-12);
    EXPECT_EQ(effect.variables[1].value->describe(), "{1920.0, 1080.0}");
    EXPECT_EQ(effect.variables[2].name, "Bins");
    EXPECT_EQ(effect.variables[2].type.arrayLength, 64);

    Lines functions;
    for (const ReshadeFunction& f : effect.functions)
        functions.push_back(f.name + " " + place(f.where) + " body " + place(f.body.where) + ".." +
                            std::to_string(pre.out.origin(1 + static_cast<int>(std::count(pre.out.code.begin(),
                                                                                            pre.out.code.begin() + static_cast<std::ptrdiff_t>(f.body.end), '\n'))).line));
    EXPECT_EQ(functions, (Lines{"ReShade::GetLinearizedDepth ParserCommon.fxh:18 body ParserCommon.fxh:19..24",
                                "PostProcessVS ParserCommon.fxh:28 body ParserCommon.fxh:29..33",
                                "BlurPS ParserEffect.fx:18 body ParserEffect.fx:19..27",
                                "CombinePS ParserEffect.fx:29 body ParserEffect.fx:30..32",
                                "HistogramCS ParserEffect.fx:35 body ParserEffect.fx:36..40"}));
    const ReshadeFunction& vs = effect.functions[1];
    ASSERT_EQ(vs.parameters.size(), 3u);
    EXPECT_EQ(vs.parameters[1].semantic, "SV_Position");
    EXPECT_EQ(vs.parameters[1].qualifiers, kReshadeOut);
    const std::string blurBody = pre.out.code.substr(effect.functions[2].body.begin,
                                                     effect.functions[2].body.end - effect.functions[2].body.begin);
    EXPECT_EQ(blurBody.substr(0, 3), "{\n\t");
    EXPECT_NE(blurBody.find("tex2D(ReShade::BackBuffer, uv + offset);\n\t}\n\treturn sum / 5;\n}"), std::string::npos);

    ASSERT_EQ(effect.techniques.size(), 2u);
    const ReshadeTechnique& bloom = effect.techniques[0];
    EXPECT_EQ(bloom.name, "FixtureBloom");
    EXPECT_EQ(place(bloom.where), "ParserEffect.fx:42");
    EXPECT_EQ(findAnnotation(bloom.annotations, "ui_label")->value.text, "Fixture Bloom");
    ASSERT_EQ(bloom.passes.size(), 2u);
    EXPECT_EQ(bloom.passes[0].name, "Blur");
    EXPECT_EQ(place(bloom.passes[0].where), "ParserEffect.fx:44");
    EXPECT_EQ(bloom.passes[0].vertexShader, "PostProcessVS");
    EXPECT_EQ(bloom.passes[0].pixelShader, "BlurPS");
    EXPECT_EQ(bloom.passes[0].renderTargets[0], "HalfTex");
    EXPECT_FALSE(bloom.passes[0].blendEnable[0]);
    EXPECT_EQ(bloom.passes[1].pixelShader, "CombinePS");
    EXPECT_EQ(bloom.passes[1].renderTargets[0], "");
    EXPECT_TRUE(bloom.passes[1].blendEnable[0]);
    EXPECT_EQ(bloom.passes[1].srcBlend[0], ReshadeBlendFactor::One);
    EXPECT_EQ(bloom.passes[1].destBlend[0], ReshadeBlendFactor::InvSrcAlpha);
    const ReshadeTechnique& histogram = effect.techniques[1];
    EXPECT_EQ(findAnnotation(histogram.annotations, "enabled")->value.describe(), "false");
    EXPECT_EQ(findAnnotation(histogram.annotations, "hidden")->value.describe(), "true");
    ASSERT_EQ(histogram.passes.size(), 1u);
    EXPECT_EQ(histogram.passes[0].computeShader, "HistogramCS");
    EXPECT_EQ(histogram.passes[0].threadGroupSize, (std::array<int, 3>{8, 8, 1}));
    EXPECT_EQ(histogram.passes[0].dispatchSize, (std::array<int, 3>{32, 1, 1}));
    EXPECT_EQ(place(histogram.passes[0].states[0].where), "ParserEffect.fx:64");
    EXPECT_EQ(histogram.passes[0].states[0].value, "HistogramCS<8, 8>");
}

}  // namespace rmfx
