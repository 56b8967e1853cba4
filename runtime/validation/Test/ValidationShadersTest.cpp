// Validation of shaders: compile errors located where they are, uniforms and samplers against the
// workspace's variables and samplers, structure only when compiling is off, the default workspace.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "frontend/workspace/DefaultWorkspace.h"
#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationShaders, CompileErrorInAnIncludedFileIsLocatedThere) {
    test::ScratchDir dir;
    dir.write("common.glsl", lines({"// helpers", "float helper() {", "    return undefinedThing;", "}"}));
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#version 450 core",
                           "#include \"common.glsl\"",
                           "out vec4 c; void main() { c = vec4(helper()); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_GE(l.errors.size(), 1u);
    EXPECT_EQ(l.errors[0], l.folder + "common.glsl:3: error: <pass name=\"p\">: 'undefinedThing' : undeclared identifier");
}

TEST(ValidationShaders, CompileErrorInInlineCodeIsLocatedInTheWorkspace) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#version 450 core",
                           "uniform float Gain;",
                           "out vec4 c;",
                           "void main() {",
                           "    c = vec4(Gain) * brightness;",
                           "}",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_GE(l.errors.size(), 1u);
    EXPECT_EQ(l.errors[0], l.path + ":9: error: <pass name=\"p\">: 'brightness' : undeclared identifier");
}

TEST(ValidationShaders, CompileErrorInAShaderFile) {
    test::ScratchDir dir;
    dir.write("shaders/p.frag", lines({"#version 450 core", "out vec4 c;", "void main() {", "    c = vec4(missing);", "}"}));
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\" file=\"shaders/p.frag\"/>",
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_GE(l.errors.size(), 1u);
    EXPECT_EQ(l.errors[0], l.folder + "shaders/p.frag:4: error: <pass name=\"p\">: 'missing' : undeclared identifier");
}

TEST(ValidationShaders, UniformTypeDisagreesWithItsVariable) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#version 450 core",
                           "uniform vec3 Gain;",
                           "out vec4 c;",
                           "void main() { c = vec4(Gain, 1.0); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":6: error: <pass name=\"p\">: uniform 'Gain' is declared vec3, but variable "
                                        "'Gain' (" + l.path + ":2) is a float (binds to GLSL float)"}));
}

TEST(ValidationShaders, UniformTypeDisagreesWithAPassConstant) {
    test::ScratchDir dir;
    dir.write("p.frag", lines({"#version 450 core", "uniform int Steps;", "out vec4 c;",
                               "void main() { c = vec4(float(Steps)); }"}));
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <float name=\"Steps\" value=\"4\"/>",
                           "    <shader stage=\"fragment\" file=\"p.frag\"/>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.folder + "p.frag:2: error: <pass name=\"p\">: uniform 'Steps' is declared int, but "
                                          "pass constant 'Steps' (" + l.path + ":3) is a float (binds to GLSL float)"}));
}

TEST(ValidationShaders, ActiveUniformWithoutVariable) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "uniform float Unset;",
                           "uniform float Unused;",
                           "out vec4 c;",
                           "void main() { c = vec4(Unset); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <pass name=\"p\">: uniform 'Unset' is declared float, but no "
                                        "variable, pass constant or predefined value has that name"}));
}

TEST(ValidationShaders, PredefinedOfTheWrongType) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "uniform vec3 rm_Time;",
                           "out vec4 c;",
                           "void main() { c = vec4(rm_Time, 1.0); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <pass name=\"p\">: uniform 'rm_Time' is declared vec3, but the "
                                        "predefined rm_Time is a float"}));
}

TEST(ValidationShaders, Sampler2DBoundToACubemap) {
    test::ScratchDir dir;
    dir.write("cross.png", "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <cubemap name=\"env\" file=\"cross.png\"/>",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"sky\" texture=\"env\"/>",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#version 450 core",
                           "out vec4 c;",
                           "uniform sampler2D sky;",
                           "void main() { c = texture(sky, vec2(0.5)); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":8: error: <pass name=\"p\">: uniform 'sky' is declared sampler2D, but "
                                        "<sampler name=\"sky\"> (" + l.path + ":4) binds a cube map and needs samplerCube"}));
}

TEST(ValidationShaders, SamplerUniformWithoutSampler) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "uniform sampler2D image;",
                           "out vec4 c;",
                           "void main() { c = texture(image, vec2(0.5)); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <pass name=\"p\">: uniform 'image' is declared sampler2D, but the "
                                        "pass has no <sampler name=\"image\">"}));
}

TEST(ValidationShaders, UnusedSamplerIsAWarningOnly) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"first\" target=\"a\">",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"second\">",
                           "    <sampler name=\"image\" target=\"a\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, Lines{});
    EXPECT_EQ(l.warnings, (Lines{l.path + ":7: warning: <sampler name=\"image\">: the shaders of pass 'second' do not "
                                          "use sampler 'image'"}));
    EXPECT_TRUE(l.result.ok());
}

TEST(ValidationShaders, StructureOnlyWhenCompilingIsOff) {
    test::ScratchDir dir;
    auto path = dir.write("fx.xml", lines({
                                        "<workspace version=\"1\">",
                                        "  <pass name=\"p\">",
                                        "    <shader stage=\"fragment\">this is not GLSL</shader>",
                                        "  </pass>",
                                        "</workspace>",
                                    }));
    Result<Workspace> loaded = loadWorkspace(path, {.compileShaders = false});
    EXPECT_EQ(formatAll(loaded.diagnostics()), "");
    EXPECT_TRUE(loaded.ok());
    EXPECT_FALSE(loadWorkspace(path).ok());
}

TEST(ValidationShaders, DefaultWorkspaceLoadsCleanly) {
    Result<Workspace> fromFile = loadWorkspace(test::sourceDir() / "effects" / "default.xml");
    EXPECT_EQ(formatAll(fromFile.diagnostics()), "");
    EXPECT_TRUE(fromFile.ok());
    Result<Workspace> builtin = loadDefaultWorkspace();
    EXPECT_EQ(formatAll(builtin.diagnostics()), "");
    ASSERT_TRUE(builtin.ok());
    EXPECT_EQ(builtin->path, defaultWorkspaceName);
}

}  // namespace
}  // namespace rmfx
