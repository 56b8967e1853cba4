#include "frontend/shader/HlslBraceElision.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(HlslBraceElision, AFlatListGetsABracePairPerElementKeepingItsLines) {
    const std::string gausBlur = "const float2 samples[3] = {\n   -0.3, -0.4,\n   -0.8, f(1, 2),\n   0.9, -0.1,\n};\n";
    const std::string nested = nestFlatArrayInitializers(gausBlur);
    EXPECT_EQ(nested, "const float2 samples[3] = {\n   {-0.3, -0.4},\n   {-0.8, f(1, 2)},\n   {0.9, -0.1},\n};\n");
    EXPECT_EQ(std::count(nested.begin(), nested.end(), '\n'), std::count(gausBlur.begin(), gausBlur.end(), '\n'));
    // Matrices count rows × columns; comments with commas do not split; locals are rewritten too.
    EXPECT_EQ(nestFlatArrayInitializers("void f() { half2x2 m[1] = { 1, /* a, b */ 2, 3, 4 }; }"),
              "void f() { half2x2 m[1] = { {1, /* a, b */ 2, 3, 4} }; }");
    EXPECT_EQ(nestFlatArrayInitializers("int3 v[ 1 ]={1,2,3}; // x = {"), "int3 v[ 1 ]={{1,2,3}}; // x = {");
}

TEST(HlslBraceElision, AnythingElseIsLeftAsItIs) {
    for (const std::string code : {
             "float2 a[2] = { {1, 2}, {3, 4} };",       // already nested
             "float2 a[2] = { float2(1, 2), float2(3, 4) };",  // one expression per element
             "float a[4] = { 1, 2, 3, 4 };",            // scalars
             "float2 a[2] = { 1, 2, 3 };",              // neither 2 nor 4 expressions
             "float2 a[N] = { 1, 2, 3, 4 };",           // a count that is not a number
             "float2 a[2] = { 1, , 3, 4 };",            // an empty expression
             "if (x == {",                              // not a declaration
             "float2 a[2] = { 1, 2, 3, 4",              // never closed
             "= {", "", "[2] = {1,2,3,4};",
         })
        EXPECT_EQ(nestFlatArrayInitializers(code), code);
}

}  // namespace
}  // namespace rmfx
