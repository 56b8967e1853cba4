// Without GL: the XML spelling of dialects, semantics, streams and the profile; the #version
// lines each dialect gets; glslang validation of legacy GLSL 1.10 and GLSL ES 1.00.

#include <gtest/gtest.h>

#include "frontend/shader/PassProgram.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "model/SemanticValues.h"
#include "validation/GlslangCheck.h"
#include "validation/Validation.h"

namespace rmfx {
namespace {

Result<Workspace> parse(const std::string& xml) { return parseWorkspaceText(xml, "legacy.xml", "."); }

const char* kLegacyWorkspace = R"(<workspace version="1" name="legacy" profile="compatibility">
  <mat4 name="matViewProjection" semantic="ViewProjection"/>
  <pass name="mesh">
    <stream usage="position" attribute="rm_Vertex"/>
    <stream usage="texcoord" index="1"/>
    <draw mesh="plane"/>
    <shader stage="vertex" dialect="glsl110"><![CDATA[
attribute vec4 rm_Vertex;
uniform mat4 matViewProjection;
varying vec2 uv;
void main() {
    gl_Position = matViewProjection * rm_Vertex + 0.0 * ftransform();
    uv = gl_MultiTexCoord1.xy;
}
]]></shader>
    <shader stage="fragment" dialect="glsl110"><![CDATA[
varying vec2 uv;
void main() { gl_FragColor = vec4(uv, gl_LightSource[0].diffuse.r, gl_FrontMaterial.diffuse.a); }
]]></shader>
  </pass>
</workspace>)";

TEST(LegacyDialects, ParserReadsProfileDialectSemanticAndStreams) {
    Result<Workspace> parsed = parse(kLegacyWorkspace);
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    EXPECT_TRUE(parsed.diagnostics().empty()) << formatAll(parsed.diagnostics());
    const Workspace& ws = *parsed;
    EXPECT_EQ(ws.profile, GlProfile::Compatibility);
    EXPECT_EQ(ws.variables.at(0).semantic, "ViewProjection");
    const Pass& pass = ws.passes.at(0);
    ASSERT_EQ(pass.streams.size(), 2u);
    EXPECT_EQ(pass.streams[0].usage, VertexUsage::Position);
    EXPECT_EQ(pass.streams[0].attribute, "rm_Vertex");
    EXPECT_EQ(pass.streams[1].usage, VertexUsage::TexCoord);
    EXPECT_EQ(pass.streams[1].usageIndex, 1);
    EXPECT_EQ(pass.streams[1].attribute, "");
    EXPECT_EQ(pass.streams[1].where.line, 5);
    ASSERT_EQ(pass.shaders.size(), 2u);
    EXPECT_EQ(pass.shaders[0].dialect, ShaderDialect::GlslLegacy);
}

TEST(LegacyDialects, ParserRejectsBadStreamsAndDialects) {
    Result<Workspace> parsed = parse(R"(<workspace version="1" profile="modern">
  <pass name="p">
    <stream usage="uv"/>
    <stream usage="normal" index="2"/>
    <stream usage="texcoord" index="9"/>
    <shader stage="fragment" dialect="glsl330">void main() {}</shader>
    <shader stage="vertex" entry="main">void main() {}</shader>
    <shader stage="vertex" matrices="row-vector">void main() {}</shader>
    <shader stage="fragment" dialect="hlsl" matrices="transposed">float4 main() : COLOR { return 1; }</shader>
  </pass>
</workspace>)");
    std::string all = formatAll(parsed.diagnostics());
    EXPECT_NE(all.find("legacy.xml:1: error: <workspace>: attribute 'profile': 'modern' is not one of: core, compatibility"),
              std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:3: error: <stream>: attribute 'usage': 'uv'"), std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:4: error: <stream>: attribute 'index' applies to usage=\"texcoord\""), std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:5: error: <stream>: attribute 'index': texture coordinate sets go from 0 to 7"),
              std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:6: error: <shader>: attribute 'dialect': 'glsl330' is not one of"), std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:7: error: <shader>: attributes 'entry' and 'profile' apply to dialect=\"hlsl\""),
              std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:8: error: <shader>: attribute 'matrices' applies to dialect=\"hlsl\""), std::string::npos) << all;
    EXPECT_NE(all.find("legacy.xml:9: error: <shader>: attribute 'matrices': 'transposed' is not one of: row-vector, column-vector"),
              std::string::npos) << all;
}

TEST(LegacyDialects, EachDialectGetsItsVersionLineAndTheDefinesFollowIt) {
    auto run = [](ShaderDialect dialect, const std::string& code) {
        ShaderInput input;
        input.code = code;
        input.start = {"s.frag", 1};
        input.dialect = dialect;
        input.defines = {"RMFX_EFFECT_a true"};
        input.declarations = {"uniform bool rmfx_effect_b;"};
        Diagnostics d;
        PreprocessedShader out = preprocessShader(input, d);
        EXPECT_TRUE(d.empty());
        EXPECT_EQ(out.lineOrigins.size(), static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n')));
        return out.code;
    };
    EXPECT_EQ(run(ShaderDialect::Glsl, "void main() {}"),
              "#version 450 core\n#define RMFX_EFFECT_a true\nuniform bool rmfx_effect_b;\nvoid main() {}\n");
    // Legacy: no #version means GLSL 1.10, and none is added.
    EXPECT_EQ(run(ShaderDialect::GlslLegacy, "void main() {}"),
              "#define RMFX_EFFECT_a true\nuniform bool rmfx_effect_b;\nvoid main() {}\n");
    EXPECT_EQ(run(ShaderDialect::GlslLegacy, "#version 120\nvoid main() {}"),
              "#version 120\n#define RMFX_EFFECT_a true\nuniform bool rmfx_effect_b;\n\nvoid main() {}\n");
    EXPECT_EQ(run(ShaderDialect::GlslEs100, "precision mediump float;\nvoid main() {}"),
              "#version 100\n#define RMFX_EFFECT_a true\nuniform bool rmfx_effect_b;\nprecision mediump float;\nvoid main() {}\n");
}

TEST(LegacyDialects, GlslangAcceptsLegacyBuiltinsAndValidationBindsTheSemantic) {
    Result<Workspace> parsed = parse(kLegacyWorkspace);
    ASSERT_TRUE(parsed.ok());
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    EXPECT_FALSE(hasErrors(d)) << formatAll(d);
}

TEST(LegacyDialects, ValidationWarnsAboutAStreamToAnAttributeTheShadersLack) {
    std::string xml = kLegacyWorkspace;
    xml.replace(xml.find("attribute=\"rm_Vertex\""), 21, "attribute=\"rm_Vertexx\"");
    Result<Workspace> parsed = parse(xml);
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_NE(all.find("legacy.xml:4: warning: <pass name=\"mesh\">: stream to attribute 'rm_Vertexx' (line 4), which the shaders do not read"),
              std::string::npos) << all;
}

TEST(LegacyDialects, LegacyGlslInACoreWorkspaceIsAnError) {
    std::string xml = kLegacyWorkspace;
    xml.replace(xml.find(" profile=\"compatibility\""), 24, "");
    Result<Workspace> parsed = parse(xml);
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_NE(all.find("legacy.xml:7: error: <shader>: legacy GLSL (dialect=\"glsl110\") in <pass name=\"mesh\"> needs a "
                       "compatibility-profile context"),
              std::string::npos) << all;
}

TEST(LegacyDialects, GlslangRejectsLegacyBuiltinsInEs100WithTheLine) {
    Result<Workspace> parsed = parse(R"(<workspace version="1">
  <pass name="es">
    <shader stage="fragment" dialect="glsles100"><![CDATA[
precision mediump float;
void main() { gl_FragColor = gl_FrontMaterial.diffuse; }
]]></shader>
  </pass>
</workspace>)");
    ASSERT_TRUE(parsed.ok());
    std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_NE(all.find("legacy.xml:5: error"), std::string::npos) << all;
    EXPECT_NE(all.find("gl_FrontMaterial"), std::string::npos) << all;
}

// Written for lenient drivers: int to float, which GLSL 1.10 does not convert implicitly.
std::string lenientWorkspace(const std::string& dialect, const std::string& versionLine = "") {
    return R"(<workspace version="1" profile="compatibility">
  <pass name="lenient">
    <shader stage="fragment" dialect=")" + dialect + R"("><![CDATA[)" + versionLine + R"(
const float PI = 3.14159265;
const float SCALE = 5 * PI;
void main() { float quarter = 1; gl_FragColor = vec4(SCALE / 100.0, quarter / 4.0, 0.0, 1.0); }
]]></shader>
  </pass>
</workspace>)";
}

TEST(LegacyDialects, ALegacyShaderWithoutVersionThat110RejectsCompilesWith120sRulesAndAWarning) {
    Result<Workspace> parsed = parse(lenientWorkspace("glsl110"));
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    Diagnostics d = validateWorkspace(*parsed).diagnostics();
    EXPECT_FALSE(hasErrors(d)) << formatAll(d);
    const std::string all = formatAll(d);
    EXPECT_NE(all.find("legacy.xml:3: warning: <pass name=\"lenient\">: fragment shader without #version: GLSL 1.10 "
                       "rejects it ("),
              std::string::npos) << all;
    EXPECT_NE(all.find("), so it is compiled with GLSL 1.20's rules (implicit int to float)"), std::string::npos) << all;
    Result<PassProgramSource> program = assemblePassProgram(*parsed, parsed->passes.at(0), {});
    ASSERT_TRUE(program) << formatAll(program.diagnostics());
    const PassStage& fragment = program->stages.at(1);
    EXPECT_EQ(fragment.shader.code.rfind("#version 120\n", 0), 0u) << fragment.shader.code;
    EXPECT_EQ(fragment.shader.origin(3).line, 4);  // "const float PI" still maps to its own line
}

TEST(LegacyDialects, NoRetryForGlslEsAnExplicitVersionOrAShaderThat120RejectsToo) {
    for (const auto& [xml, error] :
         {std::pair{lenientWorkspace("glsles100", "precision mediump float;"), std::string("legacy.xml:5: error")},
          std::pair{lenientWorkspace("glsl110", "#version 110"), std::string("legacy.xml:5: error")}}) {
        Result<Workspace> parsed = parse(xml);
        ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
        const std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
        EXPECT_NE(all.find(error), std::string::npos) << all;
        EXPECT_EQ(all.find("GLSL 1.20"), std::string::npos) << all;
    }
    std::string both = lenientWorkspace("glsl110");  // valid 1.10 but for an undeclared name
    both.replace(both.find("5 * PI"), 6, "5.0 * PI");
    both.replace(both.find("quarter = 1;"), 12, "quarter = 1.0;");
    both.replace(both.find("quarter / 4.0"), 13, "undeclared");
    Result<Workspace> parsed = parse(both);
    ASSERT_TRUE(parsed.ok());
    const std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_NE(all.find("legacy.xml:6: error: <pass name=\"lenient\">: 'undeclared' : undeclared identifier"), std::string::npos) << all;
    EXPECT_EQ(all.find("GLSL 1.20"), std::string::npos) << all;
}

TEST(LegacyDialects, BuiltinVertexShaderFollowsTheFragmentDialect) {
    EXPECT_EQ(builtinFullscreenVertexShader(ShaderDialect::GlslLegacy).rfind("#version 110\nattribute vec3 rm_Position;", 0), 0u);
    EXPECT_NE(builtinFullscreenVertexShader(ShaderDialect::GlslLegacy).find("gl_TexCoord[0]"), std::string::npos);
    EXPECT_EQ(builtinModelVertexShader(ShaderDialect::GlslEs100).rfind("#version 100\nattribute vec3 rm_Position;", 0), 0u);
    EXPECT_EQ(builtinModelVertexShader().rfind("#version 450 core\nlayout(location = 0) in vec3 rm_Position;", 0), 0u);
}

TEST(LegacyDialects, SemanticNamesMatchIgnoringCaseAndTypesFeedAsDocumented) {
    auto wvp = findSemantic("worldviewprojectioninversetranspose");
    ASSERT_TRUE(wvp);
    EXPECT_STREQ(wvp->name, "WorldViewProjectionInverseTranspose");
    EXPECT_TRUE(semanticFeeds(*wvp, UniformType::Mat4));
    EXPECT_FALSE(semanticFeeds(*wvp, UniformType::Vec4));
    auto position = findSemantic("ViewPosition");
    ASSERT_TRUE(position);
    EXPECT_TRUE(semanticFeeds(*position, UniformType::Vec3));
    EXPECT_FALSE(semanticFeeds(*position, UniformType::Float));
    EXPECT_FALSE(findSemantic("NoSuchSemantic"));
    for (double r : {randomFraction(0, 0, 1), randomFraction(7, 3, 4), randomFraction(1 << 20, -1, 2)}) {
        EXPECT_GE(r, 0.0);
        EXPECT_LT(r, 1.0);
    }
}

}  // namespace
}  // namespace rmfx
