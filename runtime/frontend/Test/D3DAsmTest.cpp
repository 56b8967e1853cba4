// Direct3D 9 shader assembly: the parser (D3DAsmParser: tokens, modifiers, masks, swizzles,
// errors at their line) and the HLSL it becomes (D3DAsmToHlsl: each instruction class, the
// register conventions, lines kept). The generated HLSL of shaders using every instruction is
// compiled by rmfx's HLSL path (glslang), so the text is checked as a compiler sees it.

#include "frontend/shader/D3DAsmParser.h"
#include "frontend/shader/D3DAsmToHlsl.h"

#include <gtest/gtest.h>

#include "frontend/shader/HlslTranslator.h"
#include "frontend/shader/ShaderPreprocessor.h"

namespace rmfx::d3dasm {
namespace {

Program parsed(const std::string& code) {
    ParseResult r = parseAssembly(code);
    for (const Message& m : r.messages) ADD_FAILURE() << "line " << m.line << ": " << m.text;
    return r.program;
}

// The first error's "line N: text", or "" when there is none.
std::string firstError(const std::vector<Message>& messages) {
    for (const Message& m : messages)
        if (m.error) return "line " + std::to_string(m.line) + ": " + m.text;
    return "";
}

std::string parseError(const std::string& code) { return firstError(parseAssembly(code).messages); }

HlslFromAsm hlslOf(const std::string& code, const std::vector<ConstantBinding>& constants = {},
                   const std::vector<SamplerBinding>& samplers = {}, const std::vector<InputRegister>& streams = {}) {
    return translateAssembly(parsed(code), constants, samplers, streams);
}

// The generated line `n` (1-based).
std::string lineOf(const std::string& text, int n) {
    size_t at = 0;
    for (int i = 1; i < n; ++i) {
        at = text.find('\n', at);
        if (at == std::string::npos) return "";
        ++at;
    }
    return text.substr(at, text.find('\n', at) - at);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// --- parser ----------------------------------------------------------------------------------

TEST(D3DAsmParser, VersionTokensWithDotsOrUnderscores) {
    EXPECT_EQ(parsed("vs.1.1").major, 1);
    EXPECT_FALSE(parsed("vs.1.1").pixel);
    Program p = parsed("ps_1_4");
    EXPECT_TRUE(p.pixel);
    EXPECT_EQ(p.minor, 4);
    EXPECT_EQ(parsed("\n\nps_2_0").line, 3);
    EXPECT_EQ(parsed("vs_2_x").minor, 1);
    EXPECT_EQ(parseError("ps.1.5"), "line 1: unknown shader version 'ps.1.5'");
    EXPECT_EQ(parseError("mov r0, c0"), "line 1: 'mov' before the version token (vs_1_1, ps_2_0…)");
    EXPECT_EQ(parseError("; only a comment\n"), "line 1: no version token (vs_1_1, ps_2_0…) in the shader");
}

TEST(D3DAsmParser, CommentsOfEveryKindAndMacros) {
    Program p = parsed("; a comment\nvs.1.1 // version\n/* a block\n over lines */ mov r0, v0 ; trailing\n"
                       "#define LIGHT c8\nmov r1, -LIGHT\n");
    ASSERT_EQ(p.instructions.size(), 2u);
    EXPECT_EQ(p.instructions[0].opcode, "mov");
    EXPECT_EQ(p.instructions[0].line, 4);
    EXPECT_EQ(p.instructions[1].sources[0].type, RegisterType::Const);
    EXPECT_EQ(p.instructions[1].sources[0].index, 8);
    EXPECT_EQ(p.instructions[1].sources[0].modifier, SourceModifier::Negate);
    EXPECT_EQ(parseError("vs.1.1\n#include \"x\"\n"), "line 2: preprocessor directive #include is not supported in assembly");
    // A macro is not expanded inside itself; macros that double at each step are cut off.
    EXPECT_EQ(parsed("vs.1.1\n#define r0 r0\nmov r0, v0\n").instructions.size(), 1u);
    std::string doubling = "vs.1.1\n#define M0 r0\n";
    for (int i = 1; i < 40; ++i) doubling += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " M" + std::to_string(i - 1) + "\n";
    EXPECT_EQ(parseError(doubling + "mov M39, v0\n"), "line 42: the macros expand this line to more than 65536 characters");
}

TEST(D3DAsmParser, DefinitionsAndDeclarations) {
    Program p = parsed("vs_2_0\ndef c3, 1.0, -0.5f, 1e-3, .25\ndefi i0, 4, 0, 1, 0\ndefb b1, true\n"
                       "dcl_texcoord1 v2\ndcl_position v0\n");
    ASSERT_EQ(p.instructions.size(), 5u);
    EXPECT_EQ(p.instructions[0].destination.index, 3);
    EXPECT_FLOAT_EQ(p.instructions[0].values[1], -0.5f);
    EXPECT_FLOAT_EQ(p.instructions[0].values[2], 1e-3f);
    EXPECT_FLOAT_EQ(p.instructions[0].values[3], 0.25f);
    EXPECT_FLOAT_EQ(p.instructions[1].values[0], 4.0f);
    EXPECT_FLOAT_EQ(p.instructions[2].values[0], 1.0f);
    EXPECT_EQ(p.instructions[3].declaration.usage, "texcoord");
    EXPECT_EQ(p.instructions[3].declaration.usageIndex, 1);
    Program s = parsed("ps_2_0\ndcl_2d s0\ndcl_cube s1\ndcl_volume s2\ndcl t0.xy\n");
    EXPECT_EQ(s.instructions[0].declaration.usage, "2d");
    EXPECT_EQ(s.instructions[1].declaration.usage, "cube");
    EXPECT_EQ(s.instructions[3].declaration.usage, "");
    EXPECT_EQ(s.instructions[3].destination.mask, 0x3u);
    EXPECT_EQ(parseError("vs_2_0\n\ndef c0, 1, 2, 3\n"), "line 3: def: expected a register and four values, found 3 operands");
    EXPECT_EQ(parseError("vs_2_0\ndef c0, 1, 2, x, 4\n"), "line 2: def: 'x' is not a number");
    EXPECT_EQ(parseError("vs_2_0\ndef c0, 1, 2, 1e99, 4\n"), "line 2: def: '1e99' is out of range");
    EXPECT_EQ(parseError("vs_2_0\ndefi i0, 1, 2.5, 0, 0\n"), "line 2: defi: '2.5' is not a 32-bit integer");
}

TEST(D3DAsmParser, ModifiersMasksAndSwizzles) {
    Program p = parsed("ps.1.1\nmad_x2_sat r0.rgb, -t0_bx2, 1-v0.a, c1_bias.xy\n+mul_d8_pp r0.a, r1_x2, -r2_bias\n");
    ASSERT_EQ(p.instructions.size(), 2u);
    const Instruction& mad = p.instructions[0];
    EXPECT_TRUE(mad.saturate);
    EXPECT_EQ(mad.shift, 1);
    EXPECT_EQ(mad.destination.mask, 0x7u);
    EXPECT_EQ(mad.sources[0].modifier, SourceModifier::SignNegate);
    EXPECT_EQ(mad.sources[1].modifier, SourceModifier::Complement);
    EXPECT_EQ(mad.sources[1].swizzle, (std::array<int, 4>{3, 3, 3, 3}));
    EXPECT_EQ(mad.sources[2].modifier, SourceModifier::Bias);
    EXPECT_EQ(mad.sources[2].swizzle, (std::array<int, 4>{0, 1, 1, 1}));  // .xy reads .xyyy
    const Instruction& mul = p.instructions[1];
    EXPECT_TRUE(mul.coissued);
    EXPECT_EQ(mul.shift, -3);
    EXPECT_EQ(mul.sources[0].modifier, SourceModifier::Times2);
    EXPECT_EQ(mul.sources[1].modifier, SourceModifier::BiasNegate);
    Program a = parsed("vs_2_0\nmov r0, c[a0.x + 3]\nmov r1, c2[a0.y]\nmov r2, -r3_abs.wzyx\n");
    EXPECT_EQ(a.instructions[0].sources[0].relativeComponent, 0);
    EXPECT_EQ(a.instructions[0].sources[0].index, 3);
    EXPECT_EQ(a.instructions[1].sources[0].relativeComponent, 1);
    EXPECT_EQ(a.instructions[1].sources[0].index, 2);
    EXPECT_EQ(a.instructions[2].sources[0].modifier, SourceModifier::AbsNegate);
    EXPECT_EQ(a.instructions[2].sources[0].swizzle, (std::array<int, 4>{3, 2, 1, 0}));
    EXPECT_TRUE(parsed("ps_2_0\ndcl_centroid t0\ntexld_pp r0, t0, s0\n").instructions.size() == 2);
    Program d = parsed("ps_3_0\ndcl_texcoord2_centroid v0\ndcl_pp v1\n");
    EXPECT_EQ(d.instructions[0].declaration.usage, "texcoord");
    EXPECT_EQ(d.instructions[0].declaration.usageIndex, 2);
    EXPECT_EQ(d.instructions[1].declaration.usage, "");
}

TEST(D3DAsmParser, ErrorsNameTheLineAndTheInstruction) {
    EXPECT_EQ(parseError("vs.1.1\nmov r0.yx, v0\n"), "line 2: write mask components must be in order (xyzw) in 'r0.yx'");
    EXPECT_EQ(parseError("vs.1.1\n\nmov r0, q7\n"), "line 3: unknown register 'q7'");
    EXPECT_EQ(parseError("vs.1.1\nmov_foo r0, v0\n"), "line 2: unknown instruction modifier '_foo' in 'mov_foo'");
    EXPECT_EQ(parseError("vs.1.1\nmov r0, v0_what\n"), "line 2: unknown source modifier '_what' in 'v0_what'");
    EXPECT_EQ(parseError("vs.1.1\nmov r0, c[a0.x + ]\n").substr(0, 7), "line 2:");
    EXPECT_EQ(parseError("vs.1.1\nmov r0, v0.xyzwx\n"), "line 2: more than four swizzle components in 'v0.xyzwx'");
    EXPECT_EQ(parseError("vs.1.1\nmov r0, c[a0.x\n"), "line 2: missing ']' in 'c[a0.x'");
    EXPECT_EQ(parseError("vs.1.1\nvs.1.1\n"), "line 2: a second version token 'vs.1.1'");
}

TEST(D3DAsmParser, NeverCrashesOnDamagedInput) {
    const std::string good = "vs.1.1\ndcl_position v0\ndef c4, 1, 2, 3, 4\nm4x4 oPos, v0, c[a0.x + 2]\nmov oT0.xy, -v0_bx2.zw\n";
    for (size_t cut = 0; cut <= good.size(); ++cut) {
        ParseResult r = parseAssembly(good.substr(0, cut));
        if (r.ok()) translateAssembly(r.program, {}, {}, {});
        std::string damaged = good;
        if (cut < good.size()) damaged[cut] = "[],.+-_#/;"[cut % 10];
        ParseResult d = parseAssembly(damaged);
        if (d.ok()) translateAssembly(d.program, {}, {}, {});
    }
}

// --- generation ------------------------------------------------------------------------------

TEST(D3DAsmToHlsl, LinesAreKeptAndEveryArithmeticInstructionIsWritten) {
    HlslFromAsm h = hlslOf(
        "vs_2_0\n"                      // 1
        "dcl_position v0\n"             // 2
        "mov r0, v0\n"                  // 3
        "add r1, r0, -v0\n"             // 4
        "sub r1, r0, v0\n"              // 5
        "mul r1, r0, v0\n"              // 6
        "mad r1, r0, v0, r0\n"          // 7
        "dp3 r1.x, r0, v0\n"            // 8
        "dp4 r1.y, r0, v0\n"            // 9
        "rcp r1.z, r0.x\n"              // 10
        "rsq r1.w, r0.y\n"              // 11
        "min r2, r0, v0\nmax r2, r0, v0\nslt r2, r0, v0\nsge r2, r0, v0\n"  // 12-15
        "exp r2, r0.x\nexpp r2, r0.x\nlog r2, r0.x\nlogp r2, r0.x\n"      // 16-19
        "lit r2, r0\ndst r2, r0, v0\nfrc r2, r0\nabs r2, r0\nnrm r2, r0\n"  // 20-24
        "pow r2, r0.x, v0.y\ncrs r2.xyz, r0, v0\nlrp r2, r0, v0, r1\n"      // 25-27
        "sincos r2.xy, r0.x\nmova a0.x, r0.x\nmov r3, c[a0.x + 1]\n"       // 28-30
        "m4x4 oPos, v0, c0\nm3x3 r4, v0, c4\nm3x2 r4, v0, c4\nm4x3 r4, v0, c4\nm3x4 r4, v0, c4\n"  // 31-35
        "sgn r5, r0, r1, r2\nnop\n");                                        // 36-37
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    EXPECT_EQ(h.entryPoint, "rm_asm_main");
    EXPECT_EQ(h.profile, "vs_3_0");
    EXPECT_TRUE(contains(lineOf(h.hlsl, 1), "void rm_asm_main(float4 v0 : POSITION0, out float4 oPos : POSITION)")) << h.hlsl;
    EXPECT_EQ(lineOf(h.hlsl, 3), "r0 = v0;");
    EXPECT_EQ(lineOf(h.hlsl, 4), "r1 = r0 + (-v0);");
    EXPECT_EQ(lineOf(h.hlsl, 7), "r1 = r0 * v0 + r0;");
    EXPECT_EQ(lineOf(h.hlsl, 8), "r1.x = (rm_rep(dot((r0).xyz, (v0).xyz))).x;");
    EXPECT_EQ(lineOf(h.hlsl, 10), "r1.z = (rm_rep(1.0 / (r0.xxxx).x)).z;");
    EXPECT_EQ(lineOf(h.hlsl, 14), "r2 = (1.0 - step(v0, r0));");
    EXPECT_EQ(lineOf(h.hlsl, 17), "r2 = rm_rep(exp2((r0.xxxx).x));");  // vs_2_0's expp is exp
    EXPECT_EQ(lineOf(h.hlsl, 26), "r2.xyz = (float4(cross((r0).xyz, (v0).xyz), 0.0)).xyz;");
    EXPECT_EQ(lineOf(h.hlsl, 27), "r2 = lerp(r1, v0, r0);");
    EXPECT_EQ(lineOf(h.hlsl, 28), "r2.xy = (float4(cos((r0.xxxx).x), sin((r0.xxxx).x), 0.0, 0.0)).xy;");
    EXPECT_EQ(lineOf(h.hlsl, 29), "a0.x = int4(floor((r0.xxxx) + 0.5)).x;");
    EXPECT_TRUE(contains(lineOf(h.hlsl, 30), "c[clamp(a0.x + 1, 0, ")) << lineOf(h.hlsl, 30);
    EXPECT_EQ(lineOf(h.hlsl, 31), "oPos = float4(dot(v0, c[0]), dot(v0, c[1]), dot(v0, c[2]), dot(v0, c[3]));");
    EXPECT_EQ(lineOf(h.hlsl, 33), "r4.xy = (float4(dot((v0).xyz, c[4].xyz), dot((v0).xyz, c[5].xyz), 0.0, 0.0)).xy;");
    EXPECT_TRUE(contains(lineOf(h.hlsl, 37), "}"));
}

TEST(D3DAsmToHlsl, Vs11ScalarsReadWWithoutASwizzleAndTheAddressRegisterRoundsToNearest) {
    HlslFromAsm h = hlslOf("vs.1.1\ndcl_position v0\nrcp r0, v0\nexpp r1, v0.x\nmov a0.x, v0.x\nmov oPos, v0\n");
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    EXPECT_EQ(lineOf(h.hlsl, 3), "r0 = rm_rep(1.0 / (v0).w);");
    EXPECT_EQ(lineOf(h.hlsl, 4), "r1 = rm_expp((v0.xxxx).x);");
    EXPECT_EQ(lineOf(h.hlsl, 5), "a0.x = int4(floor((rm_rep((v0.xxxx).x)) + 0.5)).x;");
    HlslFromAsm w = hlslOf("vs.1.1\ndcl_position v0\nmov a0.x, v0\nmov oPos, c[a0.x]\n");
    ASSERT_TRUE(w.ok()) << firstError(w.messages);
    EXPECT_EQ(lineOf(w.hlsl, 3), "a0.x = int4(floor((rm_rep((v0).w)) + 0.5)).x;");
    // Colour outputs before vs_3_0 are clamped to [0, 1].
    HlslFromAsm d = hlslOf("vs_2_0\ndcl_position v0\nmov oPos, v0\nadd oD1.xyz, v0, v0\n");
    ASSERT_TRUE(d.ok()) << firstError(d.messages);
    EXPECT_EQ(lineOf(d.hlsl, 4), "oD1.xyz = (saturate(v0 + v0)).xyz; }");
}

TEST(D3DAsmToHlsl, InstructionModifiersAndPs1xRanges) {
    HlslFromAsm h = hlslOf("ps.1.1\ndef c0, 2, 0, 0, 0\nmul_x4 r0, v0, c0\nadd_sat r1, v0_bias, 1-v1\nmov_d2 r0.a, r1.b\n");
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    // ps_1_1 reads constants clamped to [-1, 1], colours to [0, 1], and keeps temps in [-8, 8].
    EXPECT_EQ(lineOf(h.hlsl, 3), "r0 = clamp((saturate(v0) * clamp(c[0], -1.0, 1.0)) * 4.0, -8.0, 8.0);");
    EXPECT_EQ(lineOf(h.hlsl, 4), "r1 = saturate((saturate(v0) - 0.5) + (1.0 - saturate(v1)));");
    EXPECT_TRUE(contains(lineOf(h.hlsl, 5), "r0.w = (clamp((r1.zzzz) * 0.5, -8.0, 8.0)).w;")) << lineOf(h.hlsl, 5);
    EXPECT_TRUE(contains(lineOf(h.hlsl, 5), "oC0 = r0;"));
    EXPECT_TRUE(contains(lineOf(h.hlsl, 1), "float4 v0 : COLOR0, float4 v1 : COLOR1, out float4 oC0 : COLOR0")) << lineOf(h.hlsl, 1);
    HlslFromAsm p14 = hlslOf("ps.1.4\ntexld r0, t0\nmul_x8 r0, r0, r0\n");
    ASSERT_TRUE(p14.ok()) << firstError(p14.messages);
    EXPECT_TRUE(contains(lineOf(p14.hlsl, 3), "-8.0, 8.0")) << lineOf(p14.hlsl, 3);
}

TEST(D3DAsmToHlsl, ConstantRegistersFromVariablesAndDefinitions) {
    HlslFromAsm h = hlslOf("vs.1.1\ndcl_position v0\ndef c9, 1, 2, 3, 4\nm4x4 oPos, v0, c0\nmul oT0, c4, c8\nmov oT1, c9\nmov oT2, c10\n",
                           {{"stored", 0, ValueType::Mat4, 0},
                            {"light", 4, ValueType::Vec4, 0},
                            {"scale", 8, ValueType::Float, 0},
                            {"view_proj", 20, ValueType::Mat4, 0}});
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    const std::string first = lineOf(h.hlsl, 1);
    EXPECT_TRUE(contains(first, "float4x4 stored; float4 light; float scale; float4x4 view_proj;")) << first;
    // Register i is HLSL row i: VALUE_4i… of a stored matrix, row i of a semantic one (which
    // reaches HLSL transposed).
    EXPECT_TRUE(contains(first, "c[1] = float4(stored[1][0], stored[1][1], stored[1][2], stored[1][3]);")) << first;
    EXPECT_TRUE(contains(first, "c[4] = light;")) << first;
    EXPECT_TRUE(contains(first, "c[8] = float4(float(scale), 0.0, 0.0, 0.0);")) << first;
    EXPECT_TRUE(contains(first, "c[9] = float4(1.0, 2.0, 3.0, 4.0);")) << first;
    // Without relative addressing only the registers the code reads exist.
    EXPECT_FALSE(contains(first, "c[21]")) << first;
    bool warned = false;
    for (const Message& m : h.messages)
        if (!m.error && m.line == 7 && contains(m.text, "c10 is neither defined (def) nor set by an RmShaderConstant")) warned = true;
    EXPECT_TRUE(warned);

    HlslFromAsm s = hlslOf("vs_2_0\ndcl_position v0\nmova a0.x, v0.x\nmov oPos, c[a0.x]\n",
                           {{"view_proj", 0, ValueType::Mat4, 0}});
    ASSERT_TRUE(s.ok()) << firstError(s.messages);
    EXPECT_TRUE(contains(lineOf(s.hlsl, 1), "c[2] = float4(view_proj[2][0], view_proj[2][1], view_proj[2][2], view_proj[2][3]);"))
        << lineOf(s.hlsl, 1);
}

TEST(D3DAsmToHlsl, VariablesWhoseNamesCannotBeHlslGlobalsAreErrors) {
    for (const char* name : {"half", "r3", "oT1", "my value", "c"}) {
        HlslFromAsm h = hlslOf("vs_2_0\ndcl_position v0\nmov oPos, c0\n", {{name, 0, ValueType::Vec4, 3}});
        EXPECT_EQ(firstError(h.messages), "line 3: the variable '" + std::string(name) +
                                              "' of register c0 cannot be an HLSL global of that name (a keyword, a "
                                              "register's name or not an identifier), through which rmfx would bind it");
    }
    EXPECT_TRUE(hlslOf("vs_2_0\ndcl_position v0\nmov oPos, c0\n", {{"halfScale", 0, ValueType::Vec4, 0}}).ok());
}

TEST(D3DAsmToHlsl, VertexInputsByDeclarationOrStreamRegister) {
    HlslFromAsm h = hlslOf("vs.1.1\nmov oPos, v0\nmov oT1, v3\nmov oD0, v5\n", {}, {},
                           {{0, "POSITION0"}, {3, "TEXCOORD1"}, {5, "COLOR0"}});
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    EXPECT_TRUE(contains(lineOf(h.hlsl, 1), "float4 v0 : POSITION0, float4 v3 : TEXCOORD1, float4 v5 : COLOR0, "
                                            "out float4 oPos : POSITION, out float4 oD0 : COLOR0, out float4 oT1 : TEXCOORD1"))
        << lineOf(h.hlsl, 1);
    HlslFromAsm missing = hlslOf("vs.1.1\nmov oPos, v0\n\nmov oT0, v7\n", {}, {}, {{0, "POSITION0"}});
    EXPECT_EQ(firstError(missing.messages), "line 4: v7 has no dcl_* and no stream channel of the pass has REGISTER=\"7\"");
    EXPECT_EQ(firstError(hlslOf("vs_2_0\ndcl_position v0\nmov oT0, v0\n").messages), "line 1: the vertex shader never writes oPos");
}

TEST(D3DAsmToHlsl, TextureInstructionsOfEachPixelShaderVersion) {
    HlslFromAsm p11 = hlslOf("ps.1.1\ntex t0\ntexcoord t1\ntexkill t2\ntexm3x2pad t3, t0_bx2\ntexm3x2tex t4, t0_bx2\n"
                             "texreg2ar t5, t0\nmov r0, t0\n",
                             {}, {{"base", 0, SamplerKind::Texture2D}, {"env", 4, SamplerKind::Cube}});
    ASSERT_TRUE(p11.ok()) << firstError(p11.messages);
    EXPECT_EQ(lineOf(p11.hlsl, 2), "t0 = clamp(tex2D(base, (rm_tc0).xy), -8.0, 8.0);");
    EXPECT_EQ(lineOf(p11.hlsl, 3), "t1 = clamp(saturate(float4(rm_tc1.xyz, 1.0)), -8.0, 8.0);");
    EXPECT_EQ(lineOf(p11.hlsl, 4), "clip((rm_tc2).xyz);");
    EXPECT_EQ(lineOf(p11.hlsl, 5), "t3.x = dot(rm_tc3.xyz, ((2.0 * t0 - 1.0)).xyz);");
    EXPECT_TRUE(contains(lineOf(p11.hlsl, 6), "texCUBE(env, (float4(t3.x, dot(rm_tc4.xyz")) << lineOf(p11.hlsl, 6);
    EXPECT_TRUE(contains(lineOf(p11.hlsl, 1), "sampler2D base; samplerCUBE env; sampler2D rm_asm_sampler5;")) << lineOf(p11.hlsl, 1);
    bool warned = false;
    for (const Message& m : p11.messages)
        if (!m.error && m.line == 7 && contains(m.text, "no texture object is bound to sampler stage 5")) warned = true;
    EXPECT_TRUE(warned);

    HlslFromAsm p14 = hlslOf("ps.1.4\ntexld r0, t0\ntexcrd r1.rgb, t1\nphase\ntexld r2, r1_dz\nmul r0, r0, r2\n", {},
                             {{"a", 0, SamplerKind::Texture2D}, {"b", 2, SamplerKind::Texture2D}});
    ASSERT_TRUE(p14.ok()) << firstError(p14.messages);
    EXPECT_EQ(lineOf(p14.hlsl, 2), "r0 = clamp(tex2D(a, (t0).xy), -8.0, 8.0);");
    EXPECT_EQ(lineOf(p14.hlsl, 5), "r2 = clamp(tex2D(b, (rm_divz(r1)).xy), -8.0, 8.0);");

    HlslFromAsm p20 = hlslOf("ps_2_0\ndcl t0.xy\ndcl_cube s1\ndef c0, 1, 1, 1, 1\ntexld r0, t0, s1\ntexldp r1, t0, s1\n"
                             "texldb r2, t0, s1\ntexkill r0\ncmp r3, r0, r1, r2\ncnd r3, r0, r1, r2\ndp2add r4, r0, r1, c0.x\n"
                             "mov oC0, r3\nmov oDepth, r4.x\n",
                             {}, {{"sky", 1, SamplerKind::Texture2D}});
    ASSERT_TRUE(p20.ok()) << firstError(p20.messages);
    EXPECT_EQ(lineOf(p20.hlsl, 5), "r0 = texCUBE(sky, (t0).xyz);");  // dcl_cube wins over the binding
    EXPECT_EQ(lineOf(p20.hlsl, 6), "r1 = texCUBEproj(sky, t0);");
    EXPECT_EQ(lineOf(p20.hlsl, 7), "r2 = texCUBEbias(sky, t0);");
    EXPECT_EQ(lineOf(p20.hlsl, 8), "clip((r0));");
    EXPECT_EQ(lineOf(p20.hlsl, 13), "oDepth = (r4.xxxx).x; }");
}

TEST(D3DAsmToHlsl, BumpEnvironmentInstructionsReadTheStagesBumpMatrix) {
    SamplerBinding bumped{"env", 1, SamplerKind::Texture2D};
    bumped.bumpMatrix = {0.5f, 0.25f, -0.25f, 2.0f};
    bumped.bumpScale = 4.0f;
    bumped.bumpOffset = 0.5f;
    HlslFromAsm h = hlslOf("ps.1.1\ntex t0\ntexbem t1, t0\ntexbeml t2, t0_bx2\nmov r0, t1\n", {},
                           {{"bump", 0, SamplerKind::Texture2D}, bumped, {"other", 2, SamplerKind::Texture2D}});
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    EXPECT_EQ(lineOf(h.hlsl, 3), "t1 = clamp(tex2D(env, (float4(rm_tc1.x + 0.5 * (t0).x + -0.25 * (t0).y, rm_tc1.y + 0.25 * "
                                 "(t0).x + 2.0 * (t0).y, 0.0, 1.0)).xy), -8.0, 8.0);");
    // Stage 2 has the default matrix, scale and offset: 0.
    EXPECT_EQ(lineOf(h.hlsl, 4), "t2 = clamp((tex2D(other, (float4(rm_tc2.x + 0.0 * ((2.0 * t0 - 1.0)).x + 0.0 * ((2.0 * t0 - 1.0)).y, "
                                 "rm_tc2.y + 0.0 * ((2.0 * t0 - 1.0)).x + 0.0 * ((2.0 * t0 - 1.0)).y, 0.0, 1.0)).xy)) * "
                                 "(((2.0 * t0 - 1.0)).z * 0.0 + 0.0), -8.0, 8.0);");
    HlslFromAsm b = hlslOf("ps.1.4\ntexld r1, t0\ntexcrd r0.rgb, t1\nbem r1.xy, r0, r1\nphase\ntexld r1, r1\n", {}, {bumped});
    ASSERT_TRUE(b.ok()) << firstError(b.messages);
    EXPECT_EQ(lineOf(b.hlsl, 4), "r1.xy = (clamp(float4((r0).x + 0.5 * (r1).x + -0.25 * (r1).y, (r0).y + 0.25 * (r1).x + 2.0 * "
                                 "(r1).y, 0.0, 0.0), -8.0, 8.0)).xy;");
}

TEST(D3DAsmToHlsl, UnsupportedAndMisusedInstructionsAreErrorsAtTheirLine) {
    EXPECT_EQ(firstError(hlslOf("ps.1.1\ntex t0\n\ntexm3x2depth t1, t0\n").messages),
              "line 4: the instruction 'texm3x2depth' is not supported by rmfx's assembly translation");
    EXPECT_EQ(firstError(hlslOf("vs.1.1\nmov oPos, v0\nfoo r0, v0\n", {}, {}, {{0, "POSITION0"}}).messages),
              "line 3: unknown instruction 'foo'");
    EXPECT_EQ(firstError(hlslOf("vs.1.1\nmad r0, v0, v0\nmov oPos, r0\n", {}, {}, {{0, "POSITION0"}}).messages),
              "line 2: mad: expected 4 operands, found 3");
    EXPECT_EQ(firstError(hlslOf("vs_2_0\ndcl_position v0\nmov c0, v0\nmov oPos, v0\n").messages),
              "line 3: c0 is a constant register: it cannot be written");
    EXPECT_EQ(firstError(hlslOf("ps_2_0\ntexld r0, t0, c0\nmov oC0, r0\n").messages),
              "line 2: texld: the second source must be a sampler s#");
    EXPECT_EQ(firstError(hlslOf("ps.1.1\nmov oC0, v0\n").messages), "line 2: ps_1_x writes its colour to r0, not to oC#/oDepth");
    EXPECT_EQ(firstError(hlslOf("vs_2_0\ndcl_position v0\nmov oPos, c300\n").messages),
              "line 3: register index 300 is beyond Direct3D 9's 256 registers of its kind");
    EXPECT_EQ(firstError(hlslOf("vs_2_0\ndcl_position v0\nrep i0\nmov oPos, v0\n").messages),
              "line 3: rep is never closed (no matching end)");
    EXPECT_EQ(firstError(hlslOf("vs_2_0\ndcl_position v0\nbreak\nmov oPos, v0\n").messages), "line 3: break outside a rep or loop");
}

// --- the HLSL compiles -----------------------------------------------------------------------

void expectCompiles(const std::string& assembly, ShaderStage stage, const std::vector<ConstantBinding>& constants = {},
                    const std::vector<SamplerBinding>& samplers = {}) {
    HlslFromAsm h = hlslOf(assembly, constants, samplers);
    ASSERT_TRUE(h.ok()) << firstError(h.messages);
    ShaderInput input;
    input.code = h.hlsl;
    input.start = {"asm.rfx", 10};
    Diagnostics d;
    PreprocessedShader pre = preprocessShader(input, d);
    ASSERT_TRUE(d.empty()) << formatAll(d);
    Result<HlslTranslation> t = translateHlslStage(pre, {stage, h.entryPoint, h.profile}, {"asm.rfx", 9}, "<RmShader>");
    EXPECT_TRUE(t.ok()) << formatAll(t.diagnostics()) << "\n" << h.hlsl;
}

TEST(D3DAsmToHlsl, GeneratedVertexShadersCompile) {
    expectCompiles("vs.1.1\ndcl_position v0\ndcl_normal v1\ndef c20, 0.5, 1, 2, 0\n"
                   "m4x4 oPos, v0, c0\nm3x3 r0.xyz, v1, c4\ndp3 r1.x, r0, r0\nrsq r1.x, r1.x\nmul r0, r0, r1.x\n"
                   "lit r2, r0\ndst r3, r0, r1\nexpp r4, r0.x\nlogp r4, r0.y\nfrc r5, r0\nslt r6, r0, r1\nsge r6, r0, r1\n"
                   "mov a0.x, r0.x\nmov r7, c[a0.x + 8]\nmin r7, r7, c20.y\nmax r7, r7, -c20.y\nmov oD0, r7\n"
                   "mov oT0.xy, v1\nmov oFog, r0.x\nmov oPts, c20.z\n",
                   ShaderStage::Vertex, {{"view_proj_matrix", 0, ValueType::Mat4, 0}, {"tint", 8, ValueType::Vec4, 0}});
    expectCompiles("vs_2_0\ndcl_position v0\ndcl_texcoord0 v1\ndefi i0, 3, 0, 1, 0\ndefb b0, true\n"
                   "mov r0, c0\nrep i0\nadd r0, r0, v1\nendrep\nif b0\nnrm r1, r0\nelse\nabs r1, r0\nendif\n"
                   "rep i0\nif_gt r0.x, r1.x\nbreak\nendif\nendrep\n"
                   "sincos r2.xy, r0.x, c1, c2\npow r3, r0.x, r1.y\ncrs r4.xyz, r0, r1\nlrp r5, r0, r1, r2\nsgn r6, r0, r1, r2\n"
                   "mova a0.x, r0.x\nmov r7, c[a0.x + 1]\nm4x4 oPos, v0, c0\nmov oT0, r7\n"
                   "defi i1, 2, 4, 1, 0\nmov r8, c0\nloop aL, i1\nadd r8, r8, c[aL]\nendloop\nmov oT1, r8\n",
                   ShaderStage::Vertex, {{"m", 0, ValueType::Mat4, 0}});
}

TEST(D3DAsmToHlsl, GeneratedPixelShadersCompile) {
    expectCompiles("ps.1.1\ndef c0, 0.5, 0.5, 0.5, 1\ntex t0\ntexcoord t1\ntexkill t2\ntexm3x3pad t3, t0_bx2\n"
                   "texm3x3pad t4, t0_bx2\ntexm3x3vspec t5, t0_bx2\ntexreg2gb t6, t0\ntexdp3tex t7, t0\n"
                   "mul_x2 r0, t0, v0_bx2\n+mul_sat r0.a, t1.b, 1-v1.a\ncnd r1, r0.a, t5, -t6_bias\nlrp r0.rgb, c0, r0, r1\n",
                   ShaderStage::Fragment, {},
                   {{"base", 0, SamplerKind::Texture2D}, {"env", 5, SamplerKind::Cube}});
    expectCompiles("ps.1.3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\ntexm3x2pad t0, t3\n"
                   "mov r0, t3\n",
                   ShaderStage::Fragment, {{"eye", 0, ValueType::Vec4, 0}}, {});
    expectCompiles("ps.1.4\ntexld r0, t0\ntexcrd r1.rgb, t1\nphase\ntexld r2, r1_dz\ncnd r0, r0, r2, r1\n"
                   "dp3_sat r0, r0_bx2, r2_x2\n",
                   ShaderStage::Fragment, {}, {{"a", 0, SamplerKind::Texture2D}, {"b", 2, SamplerKind::Volume}});
    expectCompiles("ps_2_0\ndcl t0.xy\ndcl v0\ndcl_2d s0\ndcl_cube s1\ndcl_volume s2\ndef c0, 1, 0.5, 0, 2\n"
                   "texld r0, t0, s0\ntexldp r1, t0, s1\ntexldb r2, t0, s2\ncmp r3, r0, r1, -r2\ndp2add r4, r0, r1, c0.y\n"
                   "rcp r5.x, r4.x\nmad_sat r6, r3, r5.x, v0\nmov oC0, r6\nmov oDepth, c0.y\n",
                   ShaderStage::Fragment);
    expectCompiles("ps_3_0\ndcl_texcoord0 v0.xy\ndcl_color v1\ndcl vFace\ndcl_2d s0\ntexld r0, v0, s0\n"
                   "texldl r1, v0, s0\ndsx r2, v0\ndsy r3, v0\ntexldd r4, v0, s0, r2, r3\nmul r0, r0, v1\n"
                   "add oC0, r0, r1_abs\n",
                   ShaderStage::Fragment);
}

}  // namespace
}  // namespace rmfx::d3dasm
