#include "frontend/shader/BracketNesting.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(BracketNesting, WellNestedCodeHasNoMismatch) {
    EXPECT_FALSE(findBracketMismatch("float4 main(float3 t[2] : TEXCOORD0) : COLOR0 { return t[(1)].xyzz; }"));
    EXPECT_FALSE(findBracketMismatch("float a[2] = {1, 2}; // ) ] }\n/* ( [ { */ float b = a[0] > 0 ? a[1] : 0;"));
    EXPECT_FALSE(findBracketMismatch("string s = \"(]\"; char c = ')';"));
}

TEST(BracketNesting, AnUnclosedBracketInAParameterListIsFoundAtItsCloser) {
    // What crashed glslang's HLSL grammar (tests/fuzz-regressions/rfx_import/hlsl-unclosed-bracket-in-parameter-list).
    auto bad = findBracketMismatch("struct S { float x; };\nS vs_main(float4 p : POSITION,\n  float3 T[angent : TANGENT0, float2 s : TEXCOORD1)\n{}");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->line, 3);
    EXPECT_EQ(bad->message, "')' closes the '[' opened at line 3");
}

TEST(BracketNesting, ACloserWithNoOpenerIsFound) {
    auto bad = findBracketMismatch("float a;\n/* ] */\nfloat b; }");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->line, 3);
    EXPECT_EQ(bad->message, "'}' closes nothing");
}

TEST(BracketNesting, AnOpenerNeverClosedIsFoundAtTheOpener) {
    // What crashed glslang's HLSL grammar (tests/fuzz-regressions/rfx_import/hlsl-bracket-open-at-end).
    auto bad = findBracketMismatch("struct{float T;}o[");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->line, 1);
    EXPECT_EQ(bad->message, "'[' is never closed");

    bad = findBracketMismatch("void f(\n// )\nfloat a, {\n[\n");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->line, 1);
    EXPECT_EQ(bad->message, "'(' is never closed");
}

}  // namespace
}  // namespace rmfx
