// ReshadeParser's problems: each at the user's file and line (inside an included header, at the
// call of a macro), named by its declaration; several collected in one run; and the bounds that
// keep any input from hanging it or recursing without end.
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

}  // namespace

TEST(ReshadeParserErrors, SeveralProblemsInOneRunEachWithItsLine) {
    test::ScratchDir dir;
    test::ReshadeParse parse = test::parseText(
        dir, lines({"uniform float A = 1.0", "uniform float B < ui_min = ; > = 2;",
                    "texture T { Width = 4; Format = RGBA9; Colour = 1; };", "texture T { };",
                    "sampler S { AddressU = CLAMP; };", "sampler S2 { Texture = Nope; MinFilter = BILINEAR; };",
                    "float f() { return 1; }", "float f() { return 2; }", "static const float K;",
                    "uniform float C = some_function(2);", "}", "foo bar;", "uniform float D = 1;",
                    "float D2() { return 0; }", "static const float D2 = 1;",
                    "static const float3x3 M = float3x3(1, 0, 0, 0, 1, 0, 0, 0, 1);", "float3 M(float3 c) { return c; }"}));
    EXPECT_EQ(parse.problems(),
              (Lines{"main.fx:1: error: uniform A: expected ';', found 'uniform'",
                     "main.fx:2: error: uniform B: annotation 'ui_min': expected a value, found ';'",
                     "main.fx:3: error: texture T: 'RGBA9' is not a texture format for Format (expected R8, R16, R16F, R32I, "
                     "R32U, R32F, RG8, RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F, RGB10A2)",
                     "main.fx:3: error: texture T: unknown texture property 'Colour' (expected Width, Height, Depth, MipLevels, "
                     "Format)",
                     "main.fx:4: error: texture T: redefinition of 'T' (a texture at main.fx:3)",
                     "main.fx:5: error: sampler S: the sampler has no 'Texture' property",
                     "main.fx:6: error: sampler S2: undeclared identifier 'Nope', expected a texture",
                     "main.fx:6: error: sampler S2: 'BILINEAR' is not a filter for MinFilter (expected POINT, LINEAR, ANISOTROPIC)",
                     "main.fx:8: error: function f: redefinition of 'f' with the same parameters (at main.fx:7)",
                     "main.fx:9: error: variable K: a constant needs an initial value",
                     "main.fx:10: error: uniform C: the initial value is not a constant rmfx computes: 'some_function' is not "
                     "a function rmfx computes in a constant",
                     "main.fx:11: error: unexpected '}' (no '{' or namespace is open)", "main.fx:12: error: unknown type 'foo'",
                     "main.fx:15: error: variable D2: redefinition of 'D2' (a function at main.fx:14)"}));
    // A function after a variable of its name is not one: ReShade reads both
    ASSERT_EQ(parse.effect.functions.size(), 3u);
    EXPECT_EQ(parse.effect.functions[2].name, "M");
    // Reading went on after each
    ASSERT_EQ(parse.effect.uniforms.size(), 4u);
    EXPECT_EQ(parse.effect.uniforms[0].initializer->describe(), "1.0");
    EXPECT_EQ(parse.effect.uniforms[3].name, "D");
    EXPECT_EQ(parse.effect.textures[0].width, 4);
}

TEST(ReshadeParserErrors, UnbalancedBracesSayWhereTheBlockOpened) {
    test::ScratchDir dir;
    test::ReshadeParse body = test::parseText(
        dir, lines({"float4 PS() : SV_Target", "{", "    if (true) {", "        return 1;", "}", "technique T { pass { } }"}));
    EXPECT_EQ(body.problems(), (Lines{"main.fx:2: error: function PS: the function's '{' is never closed"}));
    EXPECT_TRUE(body.effect.techniques.empty());

    test::ReshadeParse space = test::parseText(dir, lines({"namespace N {", "  uniform float x;"}));
    EXPECT_EQ(space.problems(), (Lines{"main.fx:1: error: namespace N: the namespace's '{' is never closed"}));

    test::ReshadeParse technique = test::parseText(dir, lines({"technique T", "{", "  pass P", "  {"}));
    EXPECT_EQ(technique.problems(), (Lines{"main.fx:3: error: pass P of technique T: the pass's '{' is never closed",
                                           "main.fx:1: error: technique T: the technique's '{' is never closed"}));

    test::ReshadeParse texture = test::parseText(dir, lines({"texture T { Width = 2", "uniform float x;"}));
    EXPECT_EQ(texture.errors(), (Lines{"main.fx:1: error: texture T: expected ';', found 'uniform'"}));
}

TEST(ReshadeParserErrors, ProblemsInsideHeadersAndMacrosAtTheUsersLine) {
    test::ScratchDir dir;
    dir.write("inc.fxh", lines({"// a header", "static const int N = 4;", "texture HeaderTex { Width = N; Height = 1 / (N - 4); };"}));
    test::ReshadeParse parse = test::parseText(
        dir, lines({"#include \"inc.fxh\"", "#define MAKE_TEX(NAME, FMT) texture NAME { Format = FMT; }",
                    "MAKE_TEX(Good, RGBA8);", "MAKE_TEX(Bad,", "    RGBA7);", "#define MISSING_SEMICOLON uniform float M = 1",
                    "MISSING_SEMICOLON", "technique Tech { pass { VertexShader = Nowhere; } }"}));
    EXPECT_EQ(parse.problems(),
              (Lines{"inc.fxh:3: error: texture HeaderTex: Height: division by zero",
                     "main.fx:4: error: texture Bad: 'RGBA7' is not a texture format for Format (expected R8, R16, R16F, R32I, "
                     "R32U, R32F, RG8, RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F, RGB10A2)",
                     "main.fx:7: error: uniform M: expected ';', found 'technique'",
                     "main.fx:8: error: pass 1 of technique Tech: VertexShader: undeclared identifier 'Nowhere', expected a "
                     "function"}));
    ASSERT_EQ(parse.effect.textures.size(), 3u);
    EXPECT_EQ(parse.effect.textures[0].where.file, (dir / "inc.fxh").string());
    EXPECT_EQ(parse.effect.textures[0].where.line, 3);
    EXPECT_EQ(parse.effect.textures[0].width, 4);
    EXPECT_EQ(parse.effect.textures[1].name, "Good");
    EXPECT_EQ(parse.effect.textures[1].where.line, 3);
}

TEST(ReshadeParserErrors, BoundedForAnyInput) {
    test::ScratchDir dir;
    std::string deep;
    for (int i = 0; i < 40; ++i) deep += "namespace N" + std::to_string(i) + " { ";
    test::ReshadeParse nested = test::parseText(dir, deep + "\n");
    ASSERT_EQ(nested.errors().size(), 1u);
    EXPECT_NE(nested.errors()[0].find("namespaces nest more than 32 deep"), std::string::npos);

    test::ReshadeParse parens = test::parseText(dir, "uniform float X = " + std::string(300, '(') + "1" + std::string(300, ')') + ";\n");
    EXPECT_EQ(parens.errors(), (Lines{"main.fx:1: error: uniform X: the initial value is not a constant rmfx computes: the "
                                      "expression is nested too deep"}));

    std::string many;
    for (int i = 0; i < 300; ++i) many += "foo bar;\n";
    test::ReshadeParse flood = test::parseText(dir, many);
    ASSERT_EQ(flood.errors().size(), 101u);
    EXPECT_EQ(flood.errors().back(), "main.fx:100: error: too many errors; the rest of the effect is not read");

    // Broken starts of every construct end with errors, never a hang
    for (const char* code : {"technique", "technique T {", "technique T { pass", "technique T { pass { VertexShader = ",
                             "texture T {", "texture T { Width = ", "uniform float x <", "uniform float x < a = 1",
                             "namespace", "namespace N", "struct S {", "struct S { float", "float f(", "float f(float",
                             "float f() {", "}}}}", "<<<>>>", "sampler s { Texture = }", "static const int x = (1;",
                             "uniform float y[] ;", "\"unterminated", "@ # $", "float4 x = float4(1, 2);", "::", "a::b c;"}) {
        test::ReshadeParse broken = test::parseText(dir, std::string(code) + "\n");
        EXPECT_FALSE(broken.errors().empty()) << code;
    }
}

}  // namespace rmfx
