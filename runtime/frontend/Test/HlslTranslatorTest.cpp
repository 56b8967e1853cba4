// Direct3D 9 HLSL → GLSL (runtime/HlslTranslator): names rmfx binds by survive, the two stages
// link by semantic, errors land on the HLSL line, and a workspace's HLSL passes validate.
// The translated GLSL is checked by compiling it again with glslang (checkPassProgram), so the
// assertions are about what a GL driver would see, not about SPIRV-Cross's spelling.

#include "frontend/shader/HlslTranslator.h"

#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"
#include "validation/GlslangCheck.h"
#include "validation/Validation.h"

namespace rmfx {
namespace {

using test::lines;

// Preprocesses `code` as the passes do (a GLSL #version goes first) from effect.rfx line `line`.
PreprocessedShader preprocessed(const std::string& code, int line = 1) {
    ShaderInput input;
    input.code = code;
    input.start = {"effect.rfx", line};
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_TRUE(d.empty()) << formatAll(d);
    return out;
}

// The GLSL of translateHlslStage, its diagnostics appended to `d`; nullopt when it fails.
std::optional<PreprocessedShader> glslOf(Result<HlslTranslation> translated, Diagnostics& d) {
    d.insert(d.end(), translated.diagnostics().begin(), translated.diagnostics().end());
    if (!translated) return std::nullopt;
    return std::move(translated->glsl);
}

std::optional<PreprocessedShader> translate(const std::string& code, ShaderStage stage, Diagnostics& d,
                                            const std::string& entry = "main", const std::string& profile = "") {
    return glslOf(translateHlslStage(preprocessed(code), {stage, entry, profile}, {"effect.rfx", 7}, "<RmHLSLShader>"), d);
}

// Translates a vertex/pixel pair and links the GLSL with glslang; returns the active uniforms.
std::vector<ActiveUniform> linkPair(const std::string& vertex, const std::string& pixel) {
    Diagnostics d;
    auto vs = translate(vertex, ShaderStage::Vertex, d, "main", "vs_2_0");
    auto ps = translate(pixel, ShaderStage::Fragment, d, "main", "ps_2_0");
    if (!vs || !ps) {
        ADD_FAILURE() << formatAll(d);
        return {};
    }
    PassProgramSource program;
    program.stages.push_back({ShaderStage::Vertex, *vs, {"effect.rfx", 7}, false});
    program.stages.push_back({ShaderStage::Fragment, *ps, {"effect.rfx", 7}, false});
    auto uniforms = checkPassProgram(program, "<RmGLPass>");
    if (!uniforms) {
        ADD_FAILURE() << formatAll(d) << formatAll(uniforms.diagnostics()) << "\n" << vs->code << "\n" << ps->code;
        return {};
    }
    return *uniforms;
}

const std::string vertexShader = lines({
    "float4x4 WorldViewProjection;",
    "struct VS_OUTPUT { float4 Pos : POSITION; float4 Col : COLOR0; float2 Tex : TEXCOORD1; };",
    "VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {",
    "    VS_OUTPUT o;",
    "    o.Pos = mul(Pos, WorldViewProjection);",
    "    o.Col = float4(Tex, 0, 1);",
    "    o.Tex = Tex * 2;",
    "    return o;",
    "}",
});

// Reads its inputs in another order and under other names than the vertex shader writes them.
const std::string pixelShader = lines({
    "float4 tint;",
    "float gain;",
    "sampler2D baseMap;",
    "float4 main(float2 uv : TEXCOORD1, float4 colour : COLOR0) : COLOR {",
    "    return tex2D(baseMap, uv) * tint * gain + colour;",
    "}",
});

std::vector<std::string> names(const std::vector<ActiveUniform>& uniforms) {
    std::vector<std::string> out;
    for (const ActiveUniform& u : uniforms) out.push_back(u.name);
    std::sort(out.begin(), out.end());
    return out;
}

// Shapes that crash Debian's glslang HLSL front end (found by the rfx_import fuzzer): each is an
// error on the shader's element, and rmfx goes on.
TEST(HlslTranslator, ShadersThatCrashGlslangAreErrorsOnTheirElement) {
    // a null read in TIntermediate::addBinaryMath (brackets balanced, so the guard lets it through)
    const char* code = "float i=float4(5,5,0,0);cbuffer:register(b){float s;}float n(float Tangent:D):R{float3 "
                       "r=abs(Tangent)s.b+b++()}";
    Diagnostics d;
    EXPECT_FALSE(translate(code, ShaderStage::Fragment, d, "main", "ps_2_0"));
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].severity, Diagnostic::Severity::Error);
    EXPECT_EQ(d[0].where.file, "effect.rfx");
    EXPECT_EQ(d[0].where.line, 7);
    EXPECT_EQ(d[0].element, "<RmHLSLShader>");
    EXPECT_EQ(d[0].message.rfind("glslang crashed (signal 11", 0), 0u) << d[0].message;

    // An unclosed bracket never reaches glslang: it is reported at its own line.
    Diagnostics unclosed;
    EXPECT_FALSE(translate("float4 main() : COLOR0 { return 1; }\nstruct{float T;}o[", ShaderStage::Fragment, unclosed,
                           "main", "ps_2_0"));
    ASSERT_EQ(unclosed.size(), 1u) << formatAll(unclosed);
    EXPECT_EQ(unclosed[0].message, "'[' is never closed");
}

// glslang runs in rmfx-hlsl-worker: a worker that cannot be found or run is an error on the
// shader's element that says which program and how to point rmfx at it.
TEST(HlslTranslator, AWorkerThatCannotRunIsAnErrorSayingWhichProgram) {
    const char* code = "float4 main() : COLOR0 { return 1; }";
    struct WorkerChoice {
        explicit WorkerChoice(const char* path) { ::setenv("RMFX_HLSL_WORKER", path, 1); }
        ~WorkerChoice() { ::unsetenv("RMFX_HLSL_WORKER"); }
    };
    {
        WorkerChoice missing("/nonexistent/rmfx-hlsl-worker");
        Diagnostics d;
        EXPECT_FALSE(translate(code, ShaderStage::Fragment, d, "main", "ps_2_0"));
        ASSERT_EQ(d.size(), 1u) << formatAll(d);
        EXPECT_EQ(d[0].where.line, 7);
        EXPECT_EQ(d[0].element, "<RmHLSLShader>");
        EXPECT_EQ(d[0].message, "cannot compile this HLSL shader: RMFX_HLSL_WORKER names '/nonexistent/rmfx-hlsl-worker', "
                                "which is not a program that can be run");
    }
    {
        WorkerChoice failing("/bin/false");
        Diagnostics d;
        EXPECT_FALSE(translate(code, ShaderStage::Fragment, d, "main", "ps_2_0"));
        ASSERT_EQ(d.size(), 1u) << formatAll(d);
        EXPECT_EQ(d[0].message.rfind("glslang ended with exit status 1 before handing back its result", 0), 0u)
            << d[0].message;
    }
    Diagnostics d;
    EXPECT_TRUE(translate(code, ShaderStage::Fragment, d, "main", "ps_2_0")) << formatAll(d);
}

}  // namespace

TEST(HlslTranslator, UniformsAndSamplersKeepTheirHlslNamesAsPlainUniforms) {
    auto uniforms = linkPair(vertexShader, pixelShader);
    EXPECT_EQ(names(uniforms), (std::vector<std::string>{"WorldViewProjection", "baseMap", "gain", "tint"}));
    for (const ActiveUniform& u : uniforms) {
        if (u.name == "baseMap") {
            EXPECT_EQ(u.type, UniformType::Sampler2D);
        }
        if (u.name == "WorldViewProjection") {
            EXPECT_EQ(u.type, UniformType::Mat4);
        }
        if (u.name == "tint") {
            EXPECT_EQ(u.type, UniformType::Vec4);
        }
        if (u.name == "gain") {
            EXPECT_EQ(u.type, UniformType::Float);
        }
    }
}

// SPIRV-Cross renames names on its list of GLSL words (`noise` → `_noise`); samplers keep the
// names the pass binds, in D3D9 and D3D10 style, 2D and 3D.
TEST(HlslTranslator, SamplersNamedLikeGlslWordsKeepTheirNames) {
    auto uniforms = linkPair(vertexShader, lines({
                                               "sampler noise;",
                                               "sampler3D volume;",
                                               "Texture2D input2;",
                                               "SamplerState linearSampler;",
                                               "float4 main(float2 uv : TEXCOORD1) : COLOR0 {",
                                               "    return tex2D(noise, uv) + tex3D(volume, uv.xyx) + input2.Sample(linearSampler, uv);",
                                               "}",
                                           }));
    EXPECT_EQ(names(uniforms), (std::vector<std::string>{"WorldViewProjection", "input2", "noise", "volume"}));
    for (const ActiveUniform& u : uniforms) {
        if (u.name == "noise" || u.name == "input2") {
            EXPECT_EQ(u.type, UniformType::Sampler2D) << u.name;
        }
        if (u.name == "volume") {
            EXPECT_EQ(u.type, UniformType::Sampler3D);
        }
    }
}

TEST(HlslTranslator, CbufferMembersAreUniformsByNameBesideTheGlobals) {
    auto uniforms = linkPair(vertexShader, lines({
                                               "cbuffer Lights : register(b1) { float4 lightColour; float lightGain; };",
                                               "float4 tint;",
                                               "float4 main(float2 uv : TEXCOORD1) : COLOR {",
                                               "    return lightColour * lightGain + tint + float4(uv, 0, 0);",
                                               "}",
                                           }));
    EXPECT_EQ(names(uniforms), (std::vector<std::string>{"WorldViewProjection", "lightColour", "lightGain", "tint"}));
}

// Direct3D keeps a global's initial value until the application sets it; glslang drops it.
TEST(HlslTranslator, InitialValuesBecomeUniformInitializersAndTheOthersWarnAtTheirLine) {
    const std::string pixel = lines({
        "float4 tint = float4(0.25, 0.5, 0.75, 1);",
        "float gain = 2;",
        "int steps = 3;",
        "float3 axis = 0.5;",
        "float2x2 turn = { 0, 1, -1, 0 };",
        "float4 mixed = float4(tint.rgb, 1);",
        "float weights[3] = { 1.0 / 64.0, 6.0 / 64.0, -(1 + 2) * 0.5 };",
        "float2 offsets[2] = { {0, -1}, float2(1, 2) * 0.5 };",
        "float4 main(float2 uv : TEXCOORD1) : COLOR {",
        "    return tint * gain * steps + float4(axis, 0) + float4(mul(uv, turn), 0, 0) + mixed + weights[1] +",
        "           offsets[1].y;",
        "}",
    });
    Diagnostics d;
    auto ps = translate(pixel, ShaderStage::Fragment, d);
    ASSERT_TRUE(ps) << formatAll(d);
    for (const char* declaration : {"uniform vec4 tint = vec4(0.25, 0.5, 0.75, 1.0);", "uniform float gain = 2.0;",
                                    "uniform int steps = 3;", "uniform vec3 axis = vec3(0.5, 0.5, 0.5);",
                                    "uniform float weights[3] = float[3](0.015625, 0.09375, -1.5);",
                                    "uniform vec2 offsets[2] = vec2[2](vec2(0.0, -1.0), vec2(0.5, 1.0));",
                                    "uniform mat2 turn = mat2(0.0, 1.0, -1.0, 0.0);"})
        EXPECT_NE(ps->code.find(declaration), std::string::npos) << declaration << "\n" << ps->code;
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].severity, Diagnostic::Severity::Warning);
    EXPECT_EQ(d[0].where.line, 6);
    EXPECT_NE(d[0].message.find("'mixed' is not carried over (it is not made of numbers)"), std::string::npos)
        << d[0].message;
    // The GLSL with its initializers compiles and links.
    EXPECT_FALSE(linkPair(vertexShader, pixel).empty());
}

TEST(HlslTranslator, StagesMeetBySemanticAndPositionIsGlPositionWithDepthMapped) {
    Diagnostics d;
    auto vs = translate(vertexShader, ShaderStage::Vertex, d);
    auto ps = translate(pixelShader, ShaderStage::Fragment, d);
    ASSERT_TRUE(vs && ps) << formatAll(d);
    EXPECT_NE(vs->code.find("out vec2 " + hlslVaryingName("TEXCOORD1") + ";"), std::string::npos) << vs->code;
    EXPECT_NE(ps->code.find("in vec2 " + hlslVaryingName("texcoord1") + ";"), std::string::npos) << ps->code;
    EXPECT_NE(vs->code.find("out vec4 rm_hlsl_COLOR0;"), std::string::npos) << vs->code;
    EXPECT_NE(ps->code.find("in vec4 rm_hlsl_COLOR0;"), std::string::npos) << ps->code;
    // Direct3D's z in [0, w] becomes OpenGL's [-w, w].
    EXPECT_NE(vs->code.find("gl_Position.z = 2.0 * gl_Position.z - gl_Position.w;"), std::string::npos) << vs->code;
    EXPECT_EQ(vs->code.find("rm_hlsl_POSITION"), std::string::npos) << "POSITION must be gl_Position\n" << vs->code;
    // The mesh's position and texture coordinates arrive where rmfx's meshes put them.
    EXPECT_NE(vs->code.find("layout(location = 0) in vec4 " + hlslVertexInputName(VertexUsage::Position, 0)), std::string::npos)
        << vs->code;
    EXPECT_NE(vs->code.find("layout(location = 2) in vec2 " + hlslVertexInputName(VertexUsage::TexCoord, 0)), std::string::npos)
        << vs->code;
}

TEST(HlslTranslator, SemanticNames) {
    EXPECT_EQ(hlslVaryingName("TEXCOORD"), "rm_hlsl_TEXCOORD0");
    EXPECT_EQ(hlslVaryingName("color1"), "rm_hlsl_COLOR1");
    EXPECT_EQ(hlslVertexInputName(VertexUsage::TexCoord, 3), "rm_hlsl_in_TEXCOORD3");
    EXPECT_EQ(hlslVertexInputName(VertexUsage::Normal, 0), "rm_hlsl_in_NORMAL0");
}

TEST(HlslTranslator, LocalNamedLikeAGlobalDoesNotCaptureIt) {
    Diagnostics d;
    auto ps = translate(lines({
                            "float4 tint;",
                            "float4 twice(float4 tint) { return tint * 2; }",
                            "float4 main() : COLOR { float4 tint2 = twice(tint); return tint2; }",
                        }),
                        ShaderStage::Fragment, d);
    ASSERT_TRUE(ps) << formatAll(d);
    EXPECT_NE(ps->code.find("uniform vec4 tint;"), std::string::npos) << ps->code;
    EXPECT_NE(ps->code.find("tint_local"), std::string::npos) << ps->code;
}

TEST(HlslTranslator, ErrorsAreLocatedAtTheHlslLine) {
    ShaderInput input;
    input.code = lines({"float4 tint;", "float4 main() : COLOR {", "    return undefinedThing * tint;", "}"});
    input.start = {"effect.rfx", 40};  // the CDATA starts on line 40 of the .rfx
    Diagnostics d;
    PreprocessedShader hlsl = preprocessShader(input, d);
    auto out = glslOf(translateHlslStage(hlsl, {ShaderStage::Fragment, "main", "ps_2_0"}, {"effect.rfx", 39}, "<RmHLSLShader>"), d);
    EXPECT_FALSE(out);
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].where.file, "effect.rfx");
    EXPECT_EQ(d[0].where.line, 42);
    EXPECT_NE(d[0].message.find("undefinedThing"), std::string::npos) << formatAll(d);
    for (const Diagnostic& e : d) EXPECT_EQ(e.element, "<RmHLSLShader>");
}

// Real files carry comments in their authors' scripts (rosmontisu/AMD_RenderMonkey's RedShader.rfx,
// saved by RenderMonkey 1.82, opens its vertex shader with a Korean block comment): UTF-8 in
// comments translates, and an error after such lines is still reported at its own line.
TEST(HlslTranslator, CommentsInOtherScriptsTranslateAndKeepErrorLines) {
    const std::string comment = lines({
        "/*",
        "\xEC\xA0\x84\xEC\x97\xAD\xEB\xB3\x80\xEC\x88\x98 : \xEC\x9B\x94\xEB\x93\x9C\xED\x96\x89\xEB\xA0\xAC",  // 전역변수 : 월드행렬
        "*/",
    });
    const std::string vertex = comment + "\n" + vertexShader;
    const std::string pixel = "// \xEB\xB9\xA8\xEA\xB0\x84\xEC\x83\x89 (red)\n" + pixelShader;
    EXPECT_EQ(names(linkPair(vertex, pixel)), (std::vector<std::string>{"WorldViewProjection", "baseMap", "gain", "tint"}));

    ShaderInput input;
    input.code = comment + "\n" + lines({"float4 tint;", "float4 main() : COLOR {", "    return undefinedThing * tint;", "}"});
    input.start = {"RedShader.rfx", 40};
    Diagnostics d;
    PreprocessedShader hlsl = preprocessShader(input, d);
    EXPECT_FALSE(glslOf(translateHlslStage(hlsl, {ShaderStage::Fragment, "main", "ps_2_0"}, {"RedShader.rfx", 39}, "<RmHLSLShader>"), d));
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].where.line, 46) << formatAll(d);  // the comment (3 lines and a blank one), then the code's 3rd line
}

TEST(HlslTranslator, MissingEntryPointIsAnError) {
    Diagnostics d;
    EXPECT_FALSE(translate(pixelShader, ShaderStage::Fragment, d, "PixelMain"));
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].where.line, 7);
    EXPECT_NE(d[0].message.find("'PixelMain'"), std::string::npos) << d[0].message;
}

TEST(HlslTranslator, TargetOfTheOtherStageIsAnError) {
    Diagnostics d;
    EXPECT_FALSE(translate(pixelShader, ShaderStage::Fragment, d, "main", "vs_2_0"));
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("'vs_2_0'"), std::string::npos) << d[0].message;
    EXPECT_NE(d[0].message.find("pixel shader"), std::string::npos) << d[0].message;
    d.clear();
    EXPECT_TRUE(translate(pixelShader, ShaderStage::Fragment, d, "main", "ps_3_0")) << formatAll(d);
}

// Validation compiles a workspace's HLSL passes through the translator and locates their errors
// in the workspace file.
TEST(HlslTranslator, ValidationReportsHlslErrorsAtTheWorkspaceLine) {
    const std::string xml = lines({
        R"(<workspace version="1" name="hlsl" size="4x4">)",  // line 1
        R"(  <target name="out" format="rgba8" size="4x4"/>)",
        R"(  <pass name="p" target="out">)",
        R"(    <shader stage="fragment"><![CDATA[)",
        "float4 tint;",  // line 5
        "float4 main() : COLOR { return tint * missing; }",
        "]]></shader>",
        "  </pass>",
        "</workspace>",
    });
    Result<Workspace> parsed = parseWorkspaceText(xml, "hlsl.xml", ".");
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    for (Pass& pass : parsed->passes)
        for (ShaderSource& s : pass.shaders) {
            s.dialect = ShaderDialect::Hlsl;
            s.profile = "ps_2_0";
        }
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    ASSERT_TRUE(hasErrors(d));
    EXPECT_EQ(d[0].where.file, "hlsl.xml");
    EXPECT_EQ(d[0].where.line, 6) << formatAll(d);
    EXPECT_NE(d[0].message.find("missing"), std::string::npos) << formatAll(d);
}

}  // namespace rmfx
