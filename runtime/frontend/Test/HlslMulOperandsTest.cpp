#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/shader/HlslMulOperands.h"

namespace rmfx::test {
namespace {

TEST(HlslMulOperands, EachCallGivesItsTwoOperandsAndLineNestedCallsToo) {
    const std::string code =
        "float4x4 g_matViewProj : register(c0);\n"
        "// mul(Commented, Out)\n"
        "VS_OUTPUT main(float4 Pos : POSITION) {\n"
        "   Out.Pos = mul(g_matViewProj, float4(Pos.xyz, 1));\n"
        "   float3 n = mul ( (float3x3) World , normal );\n"
        "   float4 p = mul(mul(Pos, World), ViewProjection);\n"
        "   x = matmul(a, b) + s.mul(c, d) + mul(only) + mul(a, b, c);\n"
        "   /* mul(hidden, too) */ y = mul(arr[i], M[0]);\n"
        "}\n";
    const std::vector<MulCall> calls = mulCalls(code);
    const std::vector<std::tuple<int, std::string, std::string>> expected{{4, "g_matViewProj", "float4(Pos.xyz, 1)"},
                                                                          {5, "(float3x3) World", "normal"},
                                                                          {6, "mul(Pos, World)", "ViewProjection"},
                                                                          {6, "Pos", "World"},
                                                                          {8, "arr[i]", "M[0]"}};
    std::vector<std::tuple<int, std::string, std::string>> found;
    for (const MulCall& c : calls) found.emplace_back(c.line, c.first, c.second);
    EXPECT_EQ(found, expected);
}

TEST(HlslMulOperands, AnUnclosedCallIsLeftOut) {
    EXPECT_TRUE(mulCalls("x = mul(a, (b;\n").empty());
    EXPECT_TRUE(mulCalls("mul").empty());
    EXPECT_TRUE(mulCalls("x = mul(a, b]").empty());
}

// Code of many nested calls: each is found once, and those with long operands are left out rather
// than copied once per level.
TEST(HlslMulOperands, DeeplyNestedCallsKeepOnlyTheShortOnes) {
    const int depth = 100000;
    std::string code;
    for (int i = 0; i < depth; ++i) code += "mul(a, ";
    code += "b";
    code.append(static_cast<size_t>(depth), ')');
    const std::vector<MulCall> calls = mulCalls(code);
    ASSERT_FALSE(calls.empty());
    EXPECT_LT(calls.size(), 40u);
    EXPECT_EQ(calls.back().first, "a");
    EXPECT_EQ(calls.back().second, "b");
    for (const MulCall& call : calls) EXPECT_LE(call.second.size(), 256u);
    std::string templates;
    for (int i = 0; i < depth; ++i) templates += "matrix< ";
    EXPECT_TRUE(declaredShapes(templates).empty());
}

TEST(HlslMulOperands, AnOperandNamesAVariableOnlyWhenItIsOne) {
    EXPECT_EQ(mulOperandVariable("  World ").name, "World");
    EXPECT_EQ(mulOperandVariable("(World)").name, "World");
    EXPECT_EQ(mulOperandVariable("(float3x3) World").name, "World");
    EXPECT_EQ(mulOperandVariable("(float3x3)(World)").name, "World");
    MulOperandVariable t = mulOperandVariable("transpose( ViewProjection )");
    EXPECT_EQ(t.name, "ViewProjection");
    EXPECT_TRUE(t.transposed);
    EXPECT_FALSE(mulOperandVariable("World").transposed);
    for (const char* other : {"M[0]", "a.b", "float4(p, 1)", "2 * M", "mul(a, b)", "(a + b)", "(float3x3 World", "", "3",
                              "transpose(a, b)"})
        EXPECT_EQ(mulOperandVariable(other).name, "") << other;
}

TEST(HlslMulOperands, DeclarationsSayWhichNamesAreVectorsAndWhichMatrices) {
    const std::string code =
        "float4x4 Mvp : register(c0);\nuniform matrix<float, 4, 4> M2;\nmatrix M3;\nstatic const float3 light = float3(0, 1, 0);\n"
        "half4 colour;\nfloat scale;\n// float4 commented;\n"
        "float4 main(float4 p : POSITION, in float3 n : NORMAL) : POSITION {\n"
        "   float3x3 r = (float3x3) Mvp;\n   float4 both; float4x4 both;\n   vector v;\n   return p;\n}\n";
    const std::map<std::string, MulOperandShape> shapes = declaredShapes(code);
    const std::map<std::string, MulOperandShape> expected{
        {"Mvp", MulOperandShape::Matrix},   {"M2", MulOperandShape::Matrix}, {"M3", MulOperandShape::Matrix},
        {"light", MulOperandShape::Vector}, {"colour", MulOperandShape::Vector}, {"p", MulOperandShape::Vector},
        {"n", MulOperandShape::Vector},     {"r", MulOperandShape::Matrix},  {"v", MulOperandShape::Vector}};
    EXPECT_EQ(shapes, expected);
}

TEST(HlslMulOperands, AnOperandIsAVectorOnlyWhereTheCodeShowsIt) {
    const std::map<std::string, MulOperandShape> declared{{"p", MulOperandShape::Vector}, {"W", MulOperandShape::Matrix}};
    for (const char* vector : {"p", "(p)", "float4(p.xyz, 1)", "half3 (n)", "In.Pos", "Input . Position", "p.xyz", "(float4) q"})
        EXPECT_EQ(mulOperandShape(vector, declared), MulOperandShape::Vector) << vector;
    for (const char* matrix : {"W", "(W)", "(float4x4) S", "float3x3(a, b, c)"})
        EXPECT_EQ(mulOperandShape(matrix, declared), MulOperandShape::Matrix) << matrix;
    for (const char* unknown : {"q", "mul(p, W)", "2 * p", "arr[0]", "f(p)", "p + p", "", "In.Pos.xyz * 2", "(p"})
        EXPECT_EQ(mulOperandShape(unknown, declared), MulOperandShape::Unknown) << unknown;
}

}  // namespace
}  // namespace rmfx::test
