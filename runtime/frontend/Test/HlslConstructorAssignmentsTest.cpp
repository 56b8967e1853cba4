// fxc's constructor-as-target assignments, written out (frontend/shader/HlslConstructorAssignments).
#include "frontend/shader/HlslConstructorAssignments.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::lines;

// ATI's Iridescent Butterfly, Wings_PS: two such assignments after a multi-name declaration.
TEST(HlslConstructorAssignments, TheComponentsGoToTheNamesInOrderOnTheSameLines) {
    const std::string code = lines({
        "float4 Wings_PS(float2 Tex : TEXCOORD0, float3 Light : TEXCOORD2) : COLOR {",
        "    float3 vNormal, baseColor;",
        "    float  fGloss, fTranslucency;",
        "    float4(vNormal, fGloss) = tex2D(bump_glossMap, Tex);",
        "    float4(baseColor,",
        "           fTranslucency) = tex2D(base_opacityMap, Tex);",
        "    return float4(baseColor * fGloss, fTranslucency);",
        "}",
    });
    HlslConstructorAssignments out = writeOutConstructorAssignments(code);
    EXPECT_EQ(out.lines, (std::vector<int>{4, 5}));
    // The statement over lines 5 and 6 keeps its newline: every later line keeps its number.
    EXPECT_EQ(out.code, lines({
                            "float4 Wings_PS(float2 Tex : TEXCOORD0, float3 Light : TEXCOORD2) : COLOR {",
                            "    float3 vNormal, baseColor;",
                            "    float  fGloss, fTranslucency;",
                            "    { float4 rm_unpacked_1 = tex2D(bump_glossMap, Tex); vNormal = rm_unpacked_1.xyz; fGloss = "
                            "rm_unpacked_1.w; }",
                            "    { float4 rm_unpacked_2 =",
                            " tex2D(base_opacityMap, Tex); baseColor = rm_unpacked_2.xyz; fTranslucency = rm_unpacked_2.w; }",
                            "    return float4(baseColor * fGloss, fTranslucency);",
                            "}",
                        }));
}

TEST(HlslConstructorAssignments, ParametersAndScalarsCountTheirWidths) {
    const std::string code = "float4 main(float2 uv : TEXCOORD0, float z : TEXCOORD1) : COLOR {\n"
                             "    float w;\n"
                             "    float4(uv, z, w) = float4(1, 2, 3, 4);\n"
                             "    return float4(uv, z, w);\n}\n";
    HlslConstructorAssignments out = writeOutConstructorAssignments(code);
    EXPECT_EQ(out.code,
              "float4 main(float2 uv : TEXCOORD0, float z : TEXCOORD1) : COLOR {\n"
              "    float w;\n"
              "    { float4 rm_unpacked_1 = float4(1, 2, 3, 4); uv = rm_unpacked_1.xy; z = rm_unpacked_1.z; w = rm_unpacked_1.w; }\n"
              "    return float4(uv, z, w);\n}\n");
}

// Widths that do not fill the constructor, names not declared, expressions as targets, a
// comparison, a constructor in an expression: left for glslang.
TEST(HlslConstructorAssignments, AnythingElseIsLeftAsItIs) {
    for (const std::string body : {"float3 a; float3 b; float4(a, b) = 0;", "float4(nowhere, b) = 0;",
                                   "float3 a; float b; float4(a.xyz, b) = 0;", "float3 a; float b; if (float4(a, b) == 0) a = 1;",
                                   "float3 a; float b; float4 c = float4(a, b);", "half3 a; float b; float4(a, b) = 0;"}) {
        const std::string code = "void main() {\n    " + body + "\n}\n";
        HlslConstructorAssignments out = writeOutConstructorAssignments(code);
        EXPECT_EQ(out.code, code) << body;
        EXPECT_TRUE(out.lines.empty()) << body;
    }
    // At file scope (no function body) nothing is rewritten either.
    EXPECT_EQ(writeOutConstructorAssignments("float4(a, b) = 0;\n").code, "float4(a, b) = 0;\n");
}

}  // namespace
}  // namespace rmfx
