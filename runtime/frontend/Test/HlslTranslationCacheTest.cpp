// HlslTranslationCache: a second request with the same input is answered from the cache (the
// translator runs once), any change to what the result depends on translates anew, the warnings
// and errors come back with a cached result, the least recently used translation makes room, and
// validation and a later assembly of the same pass (the GL executor's path) share one translation.

#include "frontend/shader/HlslTranslationCache.h"

#include <random>

#include <gtest/gtest.h>

#include "frontend/shader/PassProgram.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "model/EffectSelection.h"
#include "tests/support/TestSupport.h"
#include "validation/Validation.h"

namespace rmfx {
namespace {

using test::lines;

PreprocessedShader preprocessed(const std::string& code) {
    ShaderInput input;
    input.code = code;
    input.start = {"effect.rfx", 10};
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_TRUE(d.empty()) << formatAll(d);
    return out;
}

const std::string pixelShader = lines({
    "float4 tint;",
    "float4 main(float2 uv : TEXCOORD0) : COLOR { return tint * uv.x; }",
});

const HlslStage pixelStage{ShaderStage::Fragment, "main", "ps_2_0"};
const SourceLocation where{"effect.rfx", 9};

}  // namespace

TEST(HlslTranslationCache, SecondRequestIsServedFromTheCache) {
    HlslTranslationCache cache;
    PreprocessedShader hlsl = preprocessed(pixelShader);
    Result<HlslTranslation> first = cache.translate(hlsl, pixelStage, where, "<RmHLSLShader>");
    ASSERT_TRUE(first) << first.error();
    EXPECT_EQ(cache.translations(), 1u);
    Result<HlslTranslation> second = cache.translate(hlsl, pixelStage, where, "<RmHLSLShader>");
    ASSERT_TRUE(second) << second.error();
    EXPECT_EQ(cache.translations(), 1u);
    EXPECT_EQ(cache.size(), 1u);
    EXPECT_EQ(second->glsl.code, first->glsl.code);
    EXPECT_NE(second->glsl.code.find("uniform vec4 tint;"), std::string::npos) << second->glsl.code;
    ASSERT_EQ(second->inputs.size(), 1u);
    EXPECT_EQ(second->inputs[0].semantic, "TEXCOORD0");
}

TEST(HlslTranslationCache, ChangedTextStageEntryOrProfileTranslatesAnew) {
    HlslTranslationCache cache;
    ASSERT_TRUE(cache.translate(preprocessed(pixelShader), pixelStage, where, "<RmHLSLShader>"));
    // One character of the text: tint * uv.y.
    std::string changed = pixelShader;
    changed.replace(changed.find("uv.x"), 4, "uv.y");
    Result<HlslTranslation> other = cache.translate(preprocessed(changed), pixelStage, where, "<RmHLSLShader>");
    ASSERT_TRUE(other) << other.error();
    EXPECT_EQ(cache.translations(), 2u);
    EXPECT_NE(other->glsl.code.find("uv.y"), std::string::npos) << other->glsl.code;
    // The same text for ps_3_0, then under another entry point (which it does not define).
    EXPECT_TRUE(cache.translate(preprocessed(pixelShader), {ShaderStage::Fragment, "main", "ps_3_0"}, where, "<RmHLSLShader>"));
    EXPECT_EQ(cache.translations(), 3u);
    EXPECT_FALSE(cache.translate(preprocessed(pixelShader), {ShaderStage::Fragment, "ps_main", "ps_2_0"}, where, "<RmHLSLShader>"));
    EXPECT_EQ(cache.translations(), 4u);
    EXPECT_EQ(cache.size(), 4u);
}

TEST(HlslTranslationCache, WarningsAndErrorsComeBackFromTheCache) {
    HlslTranslationCache cache;
    // `turn` keeps no initial value (it names a function): a warning at its line, 10 + 0.
    PreprocessedShader warned = preprocessed(lines({
        "float turn = sqrt(2.0);",
        "float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(uv * turn, 0, 1); }",
    }));
    PreprocessedShader broken = preprocessed(lines({"float4 main() : COLOR {", "    return missing;", "}"}));
    for (int round = 0; round < 2; ++round) {
        Result<HlslTranslation> w = cache.translate(warned, pixelStage, where, "<RmHLSLShader>");
        ASSERT_TRUE(w) << w.error();
        ASSERT_EQ(w.diagnostics().size(), 1u) << formatAll(w.diagnostics());
        EXPECT_EQ(w.diagnostics()[0].severity, Diagnostic::Severity::Warning);
        EXPECT_EQ(w.diagnostics()[0].where.line, 10);
        Result<HlslTranslation> b = cache.translate(broken, pixelStage, where, "<RmHLSLShader>");
        ASSERT_FALSE(b);
        EXPECT_EQ(b.diagnostics()[0].where.line, 11) << formatAll(b.diagnostics());
        EXPECT_NE(b.error().find("missing"), std::string::npos) << b.error();
    }
    EXPECT_EQ(cache.translations(), 2u);
}

TEST(HlslTranslationCache, LeastRecentlyUsedMakesRoom) {
    HlslTranslationCache cache(2);
    PreprocessedShader a = preprocessed(pixelShader);
    PreprocessedShader b = preprocessed(pixelShader + "\n// b\n");
    PreprocessedShader c = preprocessed(pixelShader + "\n// c\n");
    ASSERT_TRUE(cache.translate(a, pixelStage, where, "e"));
    ASSERT_TRUE(cache.translate(b, pixelStage, where, "e"));
    ASSERT_TRUE(cache.translate(a, pixelStage, where, "e"));  // a is now the most recent: b goes for c
    ASSERT_TRUE(cache.translate(c, pixelStage, where, "e"));
    EXPECT_EQ(cache.translations(), 3u);
    EXPECT_EQ(cache.size(), 2u);
    ASSERT_TRUE(cache.translate(a, pixelStage, where, "e"));
    EXPECT_EQ(cache.translations(), 3u);
    ASSERT_TRUE(cache.translate(b, pixelStage, where, "e"));
    EXPECT_EQ(cache.translations(), 4u);
}

// Validation assembles every pass; the GL executor assembles it again to compile it, through the
// same assemblePassProgram: the second assembly translates nothing.
TEST(HlslTranslationCache, ValidationAndALaterAssemblyShareOneTranslation) {
    // A value no other test uses, so that no earlier test in this process translated the same text.
    const std::string unique = std::to_string(std::random_device{}() % 100000) + ".5";
    const std::string xml = lines({
        R"(<workspace version="1" name="hlsl" size="4x4">)",
        R"(  <target name="out" format="rgba8" size="4x4"/>)",
        R"(  <pass name="p" target="out">)",
        R"(    <shader stage="fragment"><![CDATA[)",
        "float4 main(float2 uv : TEXCOORD0) : COLOR { return float4(uv, " + unique + ", 1); }",
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
    HlslTranslationCache& cache = HlslTranslationCache::shared();
    const size_t before = cache.translations();
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    ASSERT_FALSE(hasErrors(d)) << formatAll(d);
    EXPECT_EQ(cache.translations(), before + 1);
    // The executor's prelude: the effects asked for (none here).
    ShaderPrelude prelude = effectPrelude(*parsed, {});
    Result<PassProgramSource> program = assemblePassProgram(*parsed, parsed->passes[0], prelude.defines, prelude.declarations);
    ASSERT_TRUE(program) << formatAll(program.diagnostics());
    EXPECT_EQ(cache.translations(), before + 1);
    // The built-in vertex shader hands the pixel shader its TEXCOORD0, from the cached reflection.
    EXPECT_NE(program->stages[0].shader.code.find("out vec2 rm_hlsl_TEXCOORD0;"), std::string::npos)
        << program->stages[0].shader.code;
}

}  // namespace rmfx
