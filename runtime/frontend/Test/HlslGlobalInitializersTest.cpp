// The HLSL globals' initial values the translator carries over (runtime/HlslGlobalInitializers):
// which declarations count, the numbers read, and the lines they are reported at.

#include "frontend/shader/HlslGlobalInitializers.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::lines;

const HlslGlobalInitializer* find(const std::vector<HlslGlobalInitializer>& all, const std::string& name) {
    for (const auto& i : all)
        if (i.name == name) return &i;
    return nullptr;
}

TEST(HlslGlobalInitializers, ConstructorsBracesScalarsAndBooleansAtGlobalScope) {
    auto all = findHlslGlobalInitializers(lines({
        "float4 Tint = float4(0.25, 0.5, 0.75, 1.0);",  // 1
        "float Gain = 2.0f;",                           // 2
        "half Small = -.5h;",                           // 3
        "uniform float3 Axis",                          // 4
        "    = { 1, -2e-1, 3 };",                       // 5
        "bool Flag = true; int Count = 3;",             // 6
        "float4 Col : register(c3) = float4(0, 0, 0, 1);",  // 7
    }));
    ASSERT_EQ(all.size(), 7u);
    const auto* tint = find(all, "Tint");
    ASSERT_TRUE(tint);
    EXPECT_EQ(tint->declaredType, "float4");
    EXPECT_TRUE(tint->constant);
    EXPECT_EQ(tint->values, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
    EXPECT_EQ(tint->line, 1);
    EXPECT_EQ(find(all, "Gain")->values, std::vector<double>{2.0});
    EXPECT_EQ(find(all, "Small")->values, std::vector<double>{-0.5});
    EXPECT_EQ(find(all, "Axis")->values, (std::vector<double>{1.0, -0.2, 3.0}));
    EXPECT_EQ(find(all, "Axis")->line, 4);
    EXPECT_EQ(find(all, "Flag")->values, std::vector<double>{1.0});
    EXPECT_EQ(find(all, "Count")->values, std::vector<double>{3.0});
    EXPECT_EQ(find(all, "Count")->line, 6);
    EXPECT_EQ(find(all, "Col")->values, (std::vector<double>{0, 0, 0, 1}));
}

TEST(HlslGlobalInitializers, CbufferMembersCountAndFunctionBodiesStructsStaticsAndCommentsDoNot) {
    auto all = findHlslGlobalInitializers(lines({
        "#define LIMIT = 3;",
        "// float Commented = 1.0;",
        "/* float Blocked = 2.0; */",
        "static float Hidden = 1.0;",
        "const float Fixed = 2.0;",
        "struct S { float a; float b; };",
        "cbuffer Extra : register(b1)",
        "{",
        "    float4 Offset = float4(1, 2, 3, 4);",  // 9
        "    float Plain;",
        "};",
        "float4 main(float2 uv : TEXCOORD0) : COLOR",
        "{",
        "    float local = 3.0;",
        "    return float4(local, 0, 0, 1);",
        "}",
        "float After = 0.5;",  // 17
    }));
    ASSERT_EQ(all.size(), 2u) << (all.empty() ? "" : all[0].name);
    EXPECT_EQ(find(all, "Offset")->values, (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(find(all, "Offset")->line, 9);
    ASSERT_TRUE(find(all, "After"));
    EXPECT_EQ(find(all, "After")->line, 17);
}

// fxc folded constant expressions into a constant's default; anything naming another variable or
// a function is not constant, nor is a division by zero or an operation between vectors of two sizes.
TEST(HlslGlobalInitializers, ConstantExpressionsAreFoldedAndTheRestIsNotConstant) {
    auto all = findHlslGlobalInitializers(lines({
        "float4 Base = float4(1, 1, 1, 1);",
        "float4 Mix = float4(Base.rgb, 1);",
        "float Weights[3] = { 1, 2, 3 };",
        "float2x2 Turn = { 0, 1, -1, 0 };",
        "float Half = 1.0 / 2.0;",
        "float Huge = 1e999;",
        "float Endless = inf;",
        "float4 Scaled = float4(1, 2, 3, 4) * 0.5 - 1;",
        "float Kernel[2] = { -(2 + 1) * 2, 1.0/64.0, };",
        "float2 Pairs[2] = { {1, 2}, float2(3, 4.5f) };",
        "float Zero = 1 / 0;",
        "float3 Sizes = float2(1, 2) * float3(1, 2, 3);",
        "float Call = sqrt(2.0);",
        "float Unclosed = (1 + 2;",
    }));
    ASSERT_EQ(all.size(), 14u);
    EXPECT_FALSE(find(all, "Huge")->constant);
    EXPECT_FALSE(find(all, "Endless")->constant);
    EXPECT_FALSE(find(all, "Mix")->constant);
    EXPECT_TRUE(find(all, "Weights")->array);
    EXPECT_TRUE(find(all, "Weights")->constant);
    EXPECT_EQ(find(all, "Turn")->declaredType, "float2x2");
    EXPECT_EQ(find(all, "Turn")->values.size(), 4u);
    EXPECT_EQ(find(all, "Half")->values, std::vector<double>{0.5});
    EXPECT_EQ(find(all, "Scaled")->values, (std::vector<double>{-0.5, 0.0, 0.5, 1.0}));
    EXPECT_EQ(find(all, "Kernel")->values, (std::vector<double>{-6.0, 1.0 / 64.0}));
    EXPECT_EQ(find(all, "Pairs")->values, (std::vector<double>{1.0, 2.0, 3.0, 4.5}));
    // sqrt is not evaluated: Direct3D's compiler folded it, rmfx leaves it (with a warning).
    for (const char* name : {"Zero", "Sizes", "Call", "Unclosed"}) EXPECT_FALSE(find(all, name)->constant) << name;
}

}  // namespace
}  // namespace rmfx
