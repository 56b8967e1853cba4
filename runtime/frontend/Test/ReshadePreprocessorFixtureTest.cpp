// ReshadePreprocessor over a small effect written as ReShade's community writes them
// (Test/reshade/: a ReShade.fxh-like header with depth guards, BUFFER_PIXEL_SIZE, version checks
// and a ## macro that declares a texture and its sampler), compared whole with its origins.
#include "frontend/Test/ReshadePreprocessorTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;

}  // namespace

TEST(ReshadePreprocessorFixture, EffectWithHeaderExpandsWithOrigins) {
    const std::filesystem::path folder = test::sourceDir() / "runtime" / "frontend" / "Test" / "reshade";
    test::ReshadeRun run;
    ReshadeInput input;
    input.file = folder / "FixtureEffect.fx";
    run.out = preprocessReshade(input, run.diagnostics);
    EXPECT_EQ(run.problems(folder.string()), Lines{});
    EXPECT_EQ(run.solid(folder.string()),
              (Lines{"FixtureCommon.fxh:28|namespace Fixture", "FixtureCommon.fxh:29|{",
                     "FixtureCommon.fxh:30|\tfloat GetDepth(float2 texcoord)", "FixtureCommon.fxh:31|\t{",
                     "FixtureCommon.fxh:35|\t\tfloat depth = tex2Dlod(DepthBuffer, float4(texcoord, 0, 0)).x;",
                     "FixtureCommon.fxh:37|\t\tdepth = 1 - depth;", "FixtureCommon.fxh:39|\t\treturn depth;",
                     "FixtureCommon.fxh:40|\t}", "FixtureCommon.fxh:41|}",
                     "FixtureEffect.fx:18|uniform float Strength < ui_type = \"slider\"; ui_label = \"Strength (radius \" \"4\" \")\"; > = 1.0;",
                     "FixtureEffect.fx:20|texture BlurTex { Width = 1920; Height = 1080; Format = RGBA16F; }; sampler BlurSampler { Texture = BlurTex; };",
                     "FixtureEffect.fx:22|float4 PS_Blur(float4 pos : SV_Position, float2 uv : TEXCOORD) : SV_Target",
                     "FixtureEffect.fx:23|{", "FixtureEffect.fx:24|\tfloat4 sum = 0;",
                     "FixtureEffect.fx:25|\t[unroll] for (int i = -4; i <= 4; ++i)",
                     "FixtureEffect.fx:26|\t\tsum += tex2D(BlurSampler, uv + float2(i, 0) * float2((1.0 / 1920), (1.0 / 1080)));",
                     "FixtureEffect.fx:27|\treturn sum / (2 * 4 + 1) * Strength * Fixture::GetDepth(uv);", "FixtureEffect.fx:28|}",
                     "FixtureEffect.fx:30|technique FixtureBlur < ui_tooltip = \"Made for \" \"FixtureEffect\" \" on line \" \"30\"; >",
                     "FixtureEffect.fx:31|{", "FixtureEffect.fx:32|\tpass", "FixtureEffect.fx:33|\t{",
                     "FixtureEffect.fx:35|\t\tVertexShader = PostProcessVS;", "FixtureEffect.fx:37|\t\tPixelShader = PS_Blur;",
                     "FixtureEffect.fx:38|\t\tRenderTarget = BlurTex;", "FixtureEffect.fx:39|\t}", "FixtureEffect.fx:40|}"}));
    EXPECT_EQ(run.out.files, (std::vector<std::filesystem::path>{folder / "FixtureEffect.fx", folder / "FixtureCommon.fxh"}));
    Lines definitions;
    for (const ReshadeDefinition& d : run.out.definitions)
        definitions.push_back(d.name + "=" + d.value + (d.shownInUi ? " shown" : ""));
    EXPECT_EQ(definitions, (Lines{"FIXTURE_BLUR_RADIUS=4 shown", "RESHADE_DEPTH_INPUT_IS_REVERSED=1",
                                  "RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=0"}));
}

TEST(ReshadePreprocessorFixture, UserDefinitionsChangeTheEffect) {
    const std::filesystem::path folder = test::sourceDir() / "runtime" / "frontend" / "Test" / "reshade";
    test::ReshadeRun run;
    ReshadeInput input;
    input.file = folder / "FixtureEffect.fx";
    input.settings.defines = {"FIXTURE_BLUR_RADIUS=2", "RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=1"};
    input.settings.version = 30000;
    input.settings.width = 640;
    input.settings.height = 800;
    run.out = preprocessReshade(input, run.diagnostics);
    EXPECT_EQ(run.problems(folder.string()), Lines{});
    const Lines solid = run.solid(folder.string());
    auto has = [&](const std::string& line) { return std::find(solid.begin(), solid.end(), line) != solid.end(); };
    EXPECT_TRUE(has("FixtureCommon.fxh:33|\t\ttexcoord.y = 1.0 - texcoord.y;"));
    EXPECT_TRUE(has("FixtureEffect.fx:18|uniform float Strength < ui_type = \"drag\"; ui_label = \"Strength (radius \" \"2\" \")\"; > = 1.0;"));
    EXPECT_FALSE(has("FixtureEffect.fx:35|\t\tVertexShader = PostProcessVS;"));
    ASSERT_EQ(run.out.definitions.size(), 3u);
    EXPECT_EQ(run.out.definitions[0].value, "2");
    EXPECT_EQ(run.out.definitions[0].defaultValue, "4");
    EXPECT_TRUE(run.out.definitions[0].fromUser);
}

}  // namespace rmfx
