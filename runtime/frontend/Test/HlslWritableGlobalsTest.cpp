// fxc's writable copies of assigned globals, written out (frontend/shader/HlslWritableGlobals):
// which assignments count, what hides a global, and that lines stay where they were.

#include "frontend/shader/HlslWritableGlobals.h"

#include "frontend/shader/HlslGlobalInitializers.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::lines;

size_t lineCount(const std::string& s) { return static_cast<size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(HlslWritableGlobals, AssignedGlobalsGetACopySetAtTheEntryPointAndUsedEverywhere) {
    const std::string code = lines({
        "float Gain : register(c0);",
        "float4 Tint = float4(1, 0.5, 0, 1);",
        "float4x4 Unwritten;",
        "sampler2D Base;",
        "float helper() { return Gain; }",
        "float4 main(float2 uv : TEXCOORD0) : COLOR0 {",
        "    Gain *= 2;",
        "    Tint.x = helper();",
        "    return Tint * mul(Unwritten, float4(uv, 0, 1)) + tex2D(Base, uv);",
        "}",
    });
    HlslWritableGlobals out = giveWrittenGlobalsACopy(code, "main");
    EXPECT_EQ(out.written, (std::vector<std::string>{"Gain", "Tint"}));
    EXPECT_EQ(out.lines, (std::vector<int>{1, 2}));
    EXPECT_EQ(out.code, lines({
                            "float Gain : register(c0); static float rm_writable_Gain;",
                            "float4 Tint = float4(1, 0.5, 0, 1); static float4 rm_writable_Tint;",
                            "float4x4 Unwritten;",
                            "sampler2D Base;",
                            "float helper() { return rm_writable_Gain; }",
                            "float4 main(float2 uv : TEXCOORD0) : COLOR0 { rm_writable_Gain = Gain; rm_writable_Tint = Tint;",
                            "    rm_writable_Gain *= 2;",
                            "    rm_writable_Tint.x = helper();",
                            "    return rm_writable_Tint * mul(Unwritten, float4(uv, 0, 1)) + tex2D(Base, uv);",
                            "}",
                        }));
    EXPECT_EQ(lineCount(out.code), lineCount(code));
}

TEST(HlslWritableGlobals, CodeBlankedOnceServesBothScannersAlike) {
    // A comment, a string and a preprocessor line that the scanners must not read, and an
    // index that `a[a[…` style selectors walk: the BlankedHlsl overloads give what the plain ones do.
    const std::string code = lines({
        "#define X 1 // float Hidden = 1;",
        "float Gain = 2; /* float Other = 3; */",
        "float4 Tint[2] = { {1, 0, 0, 1}, {0, 1, 0, 1} };",
        "float4 main(float2 uv : TEXCOORD0) : COLOR0 {",
        "    Gain *= 2; Tint[Tint[0].x > \"]\" ? 1 : 0].y += 1;",
        "    return Tint[1] * Gain;",
        "}",
    });
    const BlankedHlsl blanked(code);
    const HlslWritableGlobals plain = giveWrittenGlobalsACopy(code, "main");
    const HlslWritableGlobals shared = giveWrittenGlobalsACopy(code, blanked, "main");
    EXPECT_EQ(plain.written, (std::vector<std::string>{"Gain", "Tint"}));
    EXPECT_EQ(shared.code, plain.code);
    EXPECT_EQ(shared.written, plain.written);
    EXPECT_EQ(shared.lines, plain.lines);
    const std::vector<HlslGlobalInitializer> initializers = findHlslGlobalInitializers(code);
    const std::vector<HlslGlobalInitializer> fromBlanked = findHlslGlobalInitializers(blanked);
    ASSERT_EQ(initializers.size(), 2u);
    ASSERT_EQ(fromBlanked.size(), initializers.size());
    for (size_t i = 0; i < initializers.size(); ++i) {
        EXPECT_EQ(fromBlanked[i].name, initializers[i].name);
        EXPECT_EQ(fromBlanked[i].line, initializers[i].line);
        EXPECT_EQ(fromBlanked[i].values, initializers[i].values);
    }
}

TEST(HlslWritableGlobals, AWriteRightAfterTheEntryPointsBraceKeepsTheCopiesInFront) {
    // The copies go in at the offset of the first use; the use is renamed after them.
    const std::string code = "float g;\nfloat4 main() : COLOR0 {g = g * 2; return g; }\n";
    EXPECT_EQ(giveWrittenGlobalsACopy(code, "main").code,
              "float g; static float rm_writable_g;\nfloat4 main() : COLOR0 { rm_writable_g = g;rm_writable_g = rm_writable_g * 2; "
              "return rm_writable_g; }\n");
}

TEST(HlslWritableGlobals, EveryKindOfAssignmentCountsAndComparisonsDoNot) {
    for (const char* statement : {"g = 1;", "g += 1;", "g -= 1;", "g /= 2;", "g++;", "--g;", "g.x = 1;", "g [0] = 1;",
                                  "g.xy *= 2;", "g <<= 1;"}) {
        SCOPED_TRACE(statement);
        const std::string code = "int4 g;\nfloat4 main() : COLOR0 { " + std::string(statement) + " return g; }\n";
        EXPECT_EQ(giveWrittenGlobalsACopy(code, "main").written, std::vector<std::string>{"g"});
    }
    for (const char* statement : {"if (g == 1) return 1;", "float4 h = g;", "return g.x <= 1 ? g : -g;", "f(g);"}) {
        SCOPED_TRACE(statement);
        const std::string code = "int4 g;\nfloat4 main() : COLOR0 { " + std::string(statement) + " return g; }\n";
        HlslWritableGlobals out = giveWrittenGlobalsACopy(code, "main");
        EXPECT_TRUE(out.written.empty());
        EXPECT_EQ(out.code, code);
    }
}

TEST(HlslWritableGlobals, WhatDeclaresTheNameItselfIsLeftAlone) {
    // A local or a parameter of the same name hides the global; a static or const global is the
    // shader's own; a comment or a string is no use.
    const std::string code = lines({
        "float a;",
        "static float b = 1;",
        "const float c = 2;",
        "float d;",
        "float f(float a) { a = 3; return a; }",
        "float4 main() : COLOR0 {",
        "    float d = 4; d += 1;",
        "    b = 2;",
        "    // a = 5;",
        "    return f(a) + b + c + d;",
        "}",
    });
    HlslWritableGlobals out = giveWrittenGlobalsACopy(code, "main");
    EXPECT_TRUE(out.written.empty());
    EXPECT_EQ(out.code, code);
}

// ATI's SpotlightWithBump: a global `lightDir` beside an output struct's member of the same name.
// `Out.lightDir.x = …` writes the member; the global is neither copied nor renamed, and where the
// global itself is written, its member namesake keeps its name.
TEST(HlslWritableGlobals, AMemberNamedLikeAGlobalIsTheMember) {
    const std::string members = lines({
        "float4 lightDir;",
        "struct VS_OUTPUT { float4 Pos : POSITION; float3 lightDir : TEXCOORD0; };",
        "VS_OUTPUT main(float4 Pos : POSITION) {",
        "    VS_OUTPUT Out;",
        "    Out.Pos = Pos;",
        "    Out.lightDir.x = dot(lightDir.xyz, Pos.xyz);",
        "    Out . lightDir.yz = lightDir.yz;",
        "    return Out;",
        "}",
    });
    HlslWritableGlobals untouched = giveWrittenGlobalsACopy(members, "main");
    EXPECT_EQ(untouched.written, std::vector<std::string>{});
    EXPECT_EQ(untouched.code, members);

    const std::string both = lines({
        "float4 lightDir;",
        "struct VS_OUTPUT { float4 Pos : POSITION; float3 lightDir : TEXCOORD0; };",
        "VS_OUTPUT main(float4 Pos : POSITION) {",
        "    VS_OUTPUT Out;",
        "    lightDir.w = 0.5;",
        "    Out.lightDir = lightDir.xyz;",
        "    Out.Pos = Pos * 1.5;",
        "    return Out;",
        "}",
    });
    HlslWritableGlobals copied = giveWrittenGlobalsACopy(both, "main");
    EXPECT_EQ(copied.written, std::vector<std::string>{"lightDir"});
    EXPECT_EQ(copied.code, lines({
                               "float4 lightDir; static float4 rm_writable_lightDir;",
                               "struct VS_OUTPUT { float4 Pos : POSITION; float3 lightDir : TEXCOORD0; };",
                               "VS_OUTPUT main(float4 Pos : POSITION) { rm_writable_lightDir = lightDir;",
                               "    VS_OUTPUT Out;",
                               "    rm_writable_lightDir.w = 0.5;",
                               "    Out.lightDir = rm_writable_lightDir.xyz;",
                               "    Out.Pos = Pos * 1.5;",
                               "    return Out;",
                               "}",
                           }));
}

TEST(HlslWritableGlobals, AGlobalWithABracedInitializerIsFoundAfterItsBraces) {
    // NVIDIA's ocean shader, as RenderMonkey files carry it: an array of structs set from constants.
    const std::string code = lines({
        "struct Wave { float freq; float amp; };",
        "Wave wave[2] = {",
        "    { 1.0, 1.0 },",
        "    { 2.0, 0.5 } };",
        "float waveFreq;",
        "float4 main(float4 P : POSITION) : POSITION {",
        "    wave[0].freq = waveFreq;",
        "    return P * wave[0].freq * wave[1].amp;",
        "}",
    });
    HlslWritableGlobals out = giveWrittenGlobalsACopy(code, "main");
    EXPECT_EQ(out.written, std::vector<std::string>{"wave"});
    EXPECT_EQ(out.lines, std::vector<int>{2});
    EXPECT_EQ(out.code, lines({
                            "struct Wave { float freq; float amp; };",
                            "Wave wave[2] = {",
                            "    { 1.0, 1.0 },",
                            "    { 2.0, 0.5 } }; static Wave rm_writable_wave[2];",
                            "float waveFreq;",
                            "float4 main(float4 P : POSITION) : POSITION { rm_writable_wave = wave;",
                            "    rm_writable_wave[0].freq = waveFreq;",
                            "    return P * rm_writable_wave[0].freq * rm_writable_wave[1].amp;",
                            "}",
                        }));
}

TEST(HlslWritableGlobals, WithoutTheEntryPointNothingChanges) {
    const std::string code = "float g;\nfloat4 ps() : COLOR0 { g = 1; return g; }\n";
    EXPECT_EQ(giveWrittenGlobalsACopy(code, "main").code, code);
    EXPECT_EQ(giveWrittenGlobalsACopy(code, "ps").written, std::vector<std::string>{"g"});
}

TEST(HlslWritableGlobals, BrokenCodeComesBackWithoutACrash) {
    for (const char* code : {"float g; float4 main() { g = ", "}}} float g; float4 main() { g = 1; }", "float4 main( { g",
                             "float g[; float4 main() { g[0 = 1; }", ""}) {
        SCOPED_TRACE(code);
        (void)giveWrittenGlobalsACopy(code, "main");
    }
}

}  // namespace rmfx
