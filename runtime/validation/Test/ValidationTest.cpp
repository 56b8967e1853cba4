#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "frontend/workspace/DefaultWorkspace.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {

namespace {

using Lines = std::vector<std::string>;
using test::lines;

// A fragment shader on one line that compiles and uses nothing.
const std::string kPlainShader = "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>";

struct Loaded {
    std::string path;       // the workspace file, as diagnostics name it
    std::string folder;     // its folder, with a trailing separator
    Result<Workspace> result;
    Lines errors, warnings;
};

// Writes the workspace as fx.xml into the scratch folder (or `sub`folder of it) and loads it.
Loaded load(const test::ScratchDir& dir, const std::string& xml, const std::string& sub = "") {
    auto path = dir.write(sub.empty() ? "fx.xml" : sub + "/fx.xml", xml);
    Loaded out{path.string(), path.parent_path().string() + "/", loadWorkspace(path), {}, {}};
    for (const Diagnostic& d : out.result.diagnostics()) {
        (d.severity == Diagnostic::Severity::Error ? out.errors : out.warnings).push_back(d.format());
    }
    if (hasErrors(out.result.diagnostics())) {
        EXPECT_FALSE(out.result.ok());
    }
    return out;
}

}  // namespace

// ---- names ----

TEST(Validation, DuplicateVariableNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <vec3 name=\"Gain\" value=\"1 2 3\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <vec3 name=\"Gain\">: duplicate variable name 'Gain' (first "
                                        "declared at line 2)"}));
}

TEST(Validation, DuplicateTargetNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "",
                           "  <target name=\"a\" format=\"rgba16f\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <target name=\"a\">: duplicate target name 'a' (first declared at "
                                        "line 2)"}));
}

TEST(Validation, FormatByNeedsAnIntVariableWithAFormatPerValue) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <int name=\"Enc\" value=\"3\"/>",
                           "  <int name=\"Mode\" value=\"0\" options=\"a, b, c\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <target name=\"a\" format=\"rgba8 rgba16f\" format-by=\"Enc\"/>",
                           "  <target name=\"b\" format=\"rgba8 rgba16f\" format-by=\"Mode\"/>",
                           "  <target name=\"c\" format=\"rgba8 rgba16f\" format-by=\"Gain\"/>",
                           "  <target name=\"d\" format=\"rgba8 rgba16f\" format-by=\"Nope\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":5: error: <target name=\"a\">: variable 'Enc' = 3 picks none of the 2 formats (values 0 to 1)",
                  l.path + ":6: error: <target name=\"b\">: format lists 2 formats, but variable 'Mode' (line 3) has 3 "
                           "options: give one format per option",
                  l.path + ":7: error: <target name=\"c\">: format-by variable 'Gain' (line 4) is a float; it must be an int",
                  l.path + ":8: error: <target name=\"d\">: format-by names 'Nope', which is not a declared variable",
              }));
}

TEST(Validation, ScaleByNeedsAnIntVariablePickingOneScale) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <int name=\"D\" value=\"3\"/>",
                           "  <int name=\"Mode\" value=\"0\" options=\"a, b\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <target name=\"a\" format=\"rgba8\" scale=\"1/2 1/4 1/8\" scale-by=\"D\"/>",
                           "  <target name=\"b\" format=\"rgba8\" scale=\"1/2 1/4 1/8\" scale-by=\"Mode\"/>",
                           "  <target name=\"c\" format=\"rgba8\" scale=\"1/2 1/4\" scale-by=\"Gain\"/>",
                           "  <target name=\"d\" format=\"rgba8\" scale=\"1/2 1/4\" scale-by=\"Nope\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":5: error: <target name=\"a\">: variable 'D' = 3 picks none of the 3 scales (values 0 to 2)",
                  l.path + ":6: error: <target name=\"b\">: scale lists 3 scales, but variable 'Mode' (line 3) has 2 "
                           "options: give one scale per option",
                  l.path + ":7: error: <target name=\"c\">: scale-by variable 'Gain' (line 4) is a float; it must be an int",
                  l.path + ":8: error: <target name=\"d\">: scale-by names 'Nope', which is not a declared variable",
              }));
}

TEST(Validation, DuplicatePassNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <pass name=\"p\">: duplicate pass name 'p' (first declared at "
                                        "line 2)"}));
}

TEST(Validation, DuplicateCubemapIsNamedAsACubemap) {
    test::ScratchDir dir;
    dir.write("a.png", "");
    dir.write("cross.png", "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <texture name=\"env\" file=\"a.png\"/>",
                           "  <cubemap name=\"env\" file=\"cross.png\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <cubemap name=\"env\">: duplicate texture name 'env' (first "
                                        "declared at line 2)"}));
}

TEST(Validation, TargetNamedOutputClashesWithTheImplicitOutput) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"output\" format=\"rgba8\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":2: error: <target name=\"output\">: the name 'output' is taken by the "
                                        "implicit output target; rename the target, or make it the output with "
                                        "<output target=\"output\"/>"}));

    // Made the output, the name is fine.
    auto ok = load(dir, lines({
                            "<workspace version=\"1\">",
                            "  <target name=\"output\" format=\"rgba8\"/>",
                            "  <pass name=\"p\">",
                            kPlainShader,
                            "  </pass>",
                            "  <output target=\"output\"/>",
                            "</workspace>",
                        }));
    EXPECT_EQ(ok.errors, Lines{});
}

TEST(Validation, WorkspaceWithoutPasses) {
    // Built in memory: no file line to point at.
    Workspace ws;
    ws.path = "mem.xml";
    EXPECT_EQ(formatAll(validateWorkspace(ws).diagnostics()), "mem.xml: error: <workspace>: no <pass>: nothing to render\n");
}

// ---- references ----

TEST(Validation, UndefinedTargetInPass) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\" target=\"nowhere\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":2: error: <pass name=\"p\">: target 'nowhere' is not declared"}));
}

TEST(Validation, UndefinedTextureAndTargetInSamplers) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"a\" texture=\"noise\"/>",
                           "    <sampler name=\"b\" target=\"blur\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":3: error: <sampler name=\"a\">: texture 'noise' is not declared",
                            l.path + ":4: error: <sampler name=\"b\">: target 'blur' is not declared",
                        }));
}

TEST(Validation, UndefinedOutputTarget) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <output target=\"final\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <output>: target 'final' is not declared"}));
}

TEST(Validation, PassSamplingWhatItWrites) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"q\">",
                           "    <sampler name=\"s\" target=\"output\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":4: error: <sampler name=\"s\">: pass 'p' samples target 'a', which it also "
                                     "writes (use frame=\"previous\" to read last frame's contents, or a second target)",
                            l.path + ":8: error: <sampler name=\"s\">: pass 'q' samples target 'output', which it "
                                     "also writes (use frame=\"previous\" to read last frame's contents, or a second "
                                     "target)",
                        }));
}

TEST(Validation, PreviousFrameOfTheWrittenTargetIsFine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = "
                           "texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"q\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = "
                           "texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, Lines{});
    EXPECT_EQ(l.warnings, Lines{});
    EXPECT_TRUE(l.result.ok());
}

TEST(Validation, MipmapFilteringNeedsMipmaps) {
    test::ScratchDir dir;
    dir.write("noise.png", "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <texture name=\"noise\" file=\"noise.png\" mipmaps=\"false\"/>",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\" mipmap=\"linear\"/>",
                           "    <sampler name=\"t\" texture=\"noise\" mipmap=\"nearest\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":5: error: <sampler name=\"s\">: mipmap filtering, but target 'a' is declared "
                                     "without mipmaps=\"true\"",
                            l.path + ":6: error: <sampler name=\"t\">: mipmap filtering, but texture 'noise' has "
                                     "mipmaps=\"false\"",
                        }));
}

TEST(Validation, MipmapFilteringOfTheImplicitOutput) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"scene\">",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"output\" mipmap=\"linear\"/>",
                           kPlainShader,
                           "  </pass>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":6: error: <sampler name=\"s\">: mipmap filtering, but the implicit output "
                                        "target has no mipmaps (declare a target with mipmaps=\"true\" and name it "
                                        "in <output target=...>)"}));
}

TEST(Validation, SecondSamplerWithTheSameName) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\"/>",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\" filter=\"nearest\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <sampler name=\"s\">: a second sampler named 's' in <pass "
                                        "name=\"p\">"}));
}

TEST(Validation, PassConstantOfAnotherType) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <pass name=\"p\">",
                           "    <vec3 name=\"Gain\" value=\"1 1 1\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <vec3 name=\"Gain\">: pass constant 'Gain' is a vec3 but variable "
                                        "'Gain' (line 2) is a float"}));
}

TEST(Validation, PassConstantColorOfAnotherWidth) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <pass name=\"p\">",
                           "    <color name=\"Tint\" value=\"1 1 1 1\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <color name=\"Tint\">: pass constant 'Tint' is a color (rgba) but "
                                        "variable 'Tint' (line 2) is a color (rgb)"}));
}

// ---- files ----

TEST(Validation, MissingImageFiles) {
    test::ScratchDir dir;
    for (const char* f : {"px.png", "nx.png", "py.png", "pz.png", "nz.png"}) dir.write(f, "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <texture name=\"t\" file=\"missing.png\"/>",
                           "  <cubemap name=\"box\">",
                           "    <face side=\"+x\" file=\"px.png\"/>",
                           "    <face side=\"-x\" file=\"nx.png\"/>",
                           "    <face side=\"+y\" file=\"py.png\"/>",
                           "    <face side=\"-y\" file=\"ny.png\"/>",
                           "    <face side=\"+z\" file=\"pz.png\"/>",
                           "    <face side=\"-z\" file=\"nz.png\"/>",
                           "  </cubemap>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":2: error: <texture name=\"t\">: image file 'missing.png' not found: looked for " +
                                l.folder + "missing.png (ignoring case); no media folders were given (add one with --media DIR)",
                            l.path + ":7: error: <cubemap name=\"box\">: image file 'ny.png' not found: looked for " +
                                l.folder + "ny.png (ignoring case); no media folders were given (add one with --media DIR)",
                        }));
}

TEST(Validation, MissingModelFile) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <draw file=\"models/rock.obj\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <draw>: model file 'models/rock.obj' not found: looked for " +
                               l.folder + "models/rock.obj (ignoring case); no media folders were given (add one with --media DIR)"}));
}

TEST(Validation, MissingShaderFile) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\" file=\"p.frag\"/>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <shader>: shader file 'p.frag' not found: looked for " +
                               l.folder + "p.frag (ignoring case); no media folders were given (add one with --media DIR)"}));
}

TEST(Validation, NoFragmentShader) {
    test::ScratchDir dir;
    dir.write("p.vert", "void main() { gl_Position = vec4(0.0); }\n");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"vertex\" file=\"p.vert\"/>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <pass name=\"p\">: no fragment shader"}));
}

// ---- includes ----

TEST(Validation, IncludeNotFound) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#include \"missing.glsl\"",
                           "out vec4 c; void main() { c = vec4(1.0); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: #include: cannot find \"missing.glsl\" (looked in " +
                               dir.path().string() + ")"}));
}

TEST(Validation, IncludeCycleNamesTheChain) {
    test::ScratchDir dir;
    dir.write("a.glsl", "#include \"b.glsl\"\n");
    dir.write("b.glsl", "// b\n#include \"a.glsl\"\n");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\"><![CDATA[",
                           "#include \"a.glsl\"",
                           "out vec4 c; void main() { c = vec4(1.0); }",
                           "]]></shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.folder + "b.glsl:2: error: #include: include cycle: \"a.glsl\" → \"b.glsl\" → "
                                          "\"a.glsl\""}));
}

TEST(Validation, ShaderFileIncludingItselfIsACycle) {
    test::ScratchDir dir;
    dir.write("self.frag", "out vec4 c;\n#include \"self.frag\"\nvoid main() { c = vec4(1.0); }\n");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <shader stage=\"fragment\" file=\"self.frag\"/>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.folder + "self.frag:2: error: #include: include cycle: \"self.frag\" → "
                                          "\"self.frag\""}));
}

TEST(Validation, IncludeOutsideTheWorkspaceFolder) {
    test::ScratchDir dir;
    dir.write("x.glsl", "float x;\n");
    auto l = load(dir,
                  lines({
                      "<workspace version=\"1\">",
                      "  <pass name=\"p\">",
                      "    <shader stage=\"fragment\"><![CDATA[",
                      "out vec4 c; void main() { c = vec4(1.0); }",
                      "#include \"../x.glsl\"",
                      "]]></shader>",
                      "  </pass>",
                      "</workspace>",
                  }),
                  "ws");
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: #include: \"../x.glsl\" lies outside the workspace folder " +
                               (dir.path() / "ws").string()}));
}

// A workspace in a subfolder of a shader library (effects/variants/ beside effects/glsl/) names the
// library's folder as its include root; the root must be an ancestor, and includes may not leave it.
TEST(Validation, IncludeRootWidensTheIncludeFolderToAnAncestor) {
    test::ScratchDir dir;
    dir.write("lib/x.glsl", "float x;\n");
    dir.write("y.glsl", "float y;\n");
    auto workspace = [](const std::string& root, const std::string& include) {
        return lines({
            "<workspace version=\"1\" include-root=\"" + root + "\">",
            "  <pass name=\"p\">",
            "    <shader stage=\"fragment\"><![CDATA[",
            "#include \"" + include + "\"",
            "out vec4 c; void main() { c = vec4(x); }",
            "]]></shader>",
            "  </pass>",
            "</workspace>",
        });
    };
    auto good = load(dir, workspace("..", "../x.glsl"), "lib/ws");
    EXPECT_EQ(good.errors, Lines{});
    auto outside = load(dir, workspace("..", "../../y.glsl"), "lib/ws");
    EXPECT_EQ(outside.errors, (Lines{outside.path + ":4: error: #include: \"../../y.glsl\" lies outside the workspace folder " +
                                     (dir.path() / "lib").string()}));
    auto sideways = load(dir, workspace("../other", "../x.glsl"), "lib/ws");
    EXPECT_EQ(sideways.errors, (Lines{sideways.path + ":1: error: <workspace>: include-root '../other' must be an ancestor "
                                                      "of the workspace folder: \"..\", \"../..\", ..."}));
}

// ---- shaders ----

TEST(Validation, CompileErrorInAnIncludedFileIsLocatedThere) {
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

TEST(Validation, CompileErrorInInlineCodeIsLocatedInTheWorkspace) {
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

TEST(Validation, CompileErrorInAShaderFile) {
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

TEST(Validation, UniformTypeDisagreesWithItsVariable) {
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

TEST(Validation, UniformTypeDisagreesWithAPassConstant) {
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

TEST(Validation, ActiveUniformWithoutVariable) {
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

TEST(Validation, PredefinedOfTheWrongType) {
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

TEST(Validation, Sampler2DBoundToACubemap) {
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

TEST(Validation, SamplerUniformWithoutSampler) {
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

TEST(Validation, UnusedSamplerIsAWarningOnly) {
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

TEST(Validation, StructureOnlyWhenCompilingIsOff) {
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

// ---- whole workspaces ----

TEST(Validation, DefaultWorkspaceLoadsCleanly) {
    Result<Workspace> fromFile = loadWorkspace(test::sourceDir() / "effects" / "default.xml");
    EXPECT_EQ(formatAll(fromFile.diagnostics()), "");
    EXPECT_TRUE(fromFile.ok());
    Result<Workspace> builtin = loadDefaultWorkspace();
    EXPECT_EQ(formatAll(builtin.diagnostics()), "");
    ASSERT_TRUE(builtin.ok());
    EXPECT_EQ(builtin->path, defaultWorkspaceName);
}

// ---- --set overrides ----

TEST(Validation, OverridesReplaceDefaults) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <bool name=\"On\" value=\"false\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_TRUE(l.result.ok());
    Workspace ws = *l.result;
    Result<void> set = applyOverrides(ws, {{"Gain", "2.5"}, {"Tint", "0.5 0.25 0"}, {"On", "true"}});
    EXPECT_TRUE(set.ok());
    EXPECT_EQ(formatAll(set.diagnostics()), "");
    EXPECT_EQ(ws.findVariable("Gain")->value, Value::ofFloat(2.5f));
    EXPECT_EQ(formatValue(ws.findVariable("Tint")->value), "0.5 0.25 0");
    EXPECT_EQ(ws.findVariable("On")->value, Value::ofBool(true));
}

TEST(Validation, OverrideErrorsNameTheVariable) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <color name=\"Fog\" value=\"1 1 1 0.5\"/>",
                           "  <int name=\"Steps\" value=\"4\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_TRUE(l.result.ok());
    Workspace ws = *l.result;
    Result<void> set = applyOverrides(ws, {{"Gian", "2"},
                                           {"Gain", "bright"},
                                           {"Tint", "1 0 0 1"},
                                           {"Fog", "1 0 0"},
                                           {"Steps", "2.5"},
                                           {"Gain", "3"}});
    EXPECT_FALSE(set.ok());
    EXPECT_EQ(formatAll(set.diagnostics()),
              l.path + ": error: --set Gian: the workspace has no variable 'Gian' (it has: Gain, Tint, Fog, Steps)\n" +
                  l.path + ":2: error: --set Gain: variable 'Gain' (float): expected numbers, got 'bright'\n" +
                  l.path + ":3: error: --set Tint: variable 'Tint' (color): this color takes 3 numbers (rgb), got 4\n" +
                  l.path + ":4: error: --set Fog: variable 'Fog' (color): this color takes 4 numbers (rgba), got 3\n" +
                  l.path + ":5: error: --set Steps: variable 'Steps' (int): expected an integer, got '2.5'\n");
    // Bad overrides leave the default; good ones still apply.
    EXPECT_EQ(ws.findVariable("Gain")->value, Value::ofFloat(3.0f));
    EXPECT_EQ(ws.findVariable("Tint")->value.type, ValueType::Color3);
    EXPECT_EQ(ws.findVariable("Steps")->value, Value::ofInt(4));

    Workspace empty;
    empty.path = "e.xml";
    EXPECT_EQ(formatAll(applyOverrides(empty, {{"X", "1"}}).diagnostics()),
              "e.xml: error: --set X: the workspace has no variable 'X' (it declares none)\n");
}

}  // namespace rmfx

namespace rmfx {

TEST(Validation, EffectsNameDeclaredPassesAndScalarSwitches) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <vec3 name=\"Tint\" value=\"1 1 1\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <effect name=\"a\" passes=\"p q\" switch=\"Gain\"/>",
                           "  <effect name=\"b\" passes=\"p\" switch=\"Tint Missing\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <output effects=\"a c\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":4: error: <effect name=\"a\">: pass 'q' is not declared",
                            l.path + ":5: error: <effect name=\"b\">: pass 'p' already belongs to effect 'a' (line 4): a "
                                     "pass belongs to one effect",
                            l.path + ":5: error: <effect name=\"b\">: switch 'Tint' (line 2) is a vec3; a switch is a "
                                     "bool, int or float",
                            l.path + ":5: error: <effect name=\"b\">: switch 'Missing' is not a declared variable",
                            l.path + ":9: error: <output>: effects: no effect named 'c' is declared",
                        }));
}

// Skipping an effect whose source holds nothing must leave what running it leaves: the checks.
TEST(Validation, AnEffectsSourceIsATargetItStartsFromAndOnlyItWritesWhatItHandsOn) {
    test::ScratchDir dir;
    const std::string reads = "    <sampler name=\"S\" target=\"src\"/>";
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <target name=\"d\" format=\"rgba8\"/>",
                           "  <effect name=\"unknown\" passes=\"p1\" source=\"nope\"/>",
                           "  <effect name=\"self\" passes=\"p2\" source=\"a\"/>",
                           "  <effect name=\"over\" passes=\"p3\" source=\"src\"/>",
                           "  <effect name=\"unread\" passes=\"p5\" source=\"src\"/>",
                           "  <effect name=\"history\" passes=\"p6\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p1\" target=\"a\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p2\" target=\"a\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p3\" target=\"b\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p4\" target=\"b\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p5\" target=\"d\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p6\" target=\"d\">",
                           reads,
                           "    <sampler name=\"H\" target=\"d\" frame=\"previous\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D S; uniform sampler2D H; out vec4 c;",
                           "      void main() { c = texture(S, vec2(0.5)) + texture(H, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":6: error: <effect name=\"unknown\">: source: no render target 'nope' (it has: src, a, b, d; the output is 'output')",
                  l.path + ":7: error: <effect name=\"self\">: source 'a' is written by pass 'p2' of the effect itself; the "
                           "source is what the effect starts from, written before it by passes outside it",
                  l.path + ":8: error: <effect name=\"over\">: pass 'p3' writes 'b', which pass 'p4' outside the effect writes "
                           "too: a skipped effect's targets are cleared to zero, which would lose what 'p4' wrote",
                  l.path + ":9: error: <effect name=\"unread\">: pass 'p5' writes 'd', which is read with frame=\"previous\": "
                           "a skipped frame could not leave what running it leaves there, so the effect cannot have a source",
                  l.path + ":9: error: <effect name=\"unread\">: pass 'p5' writes 'd', which pass 'p6' outside the effect writes "
                           "too: a skipped effect's targets are cleared to zero, which would lose what 'p6' wrote",
                  l.path + ":9: error: <effect name=\"unread\">: no pass of the effect reads its source 'src', directly or "
                           "through what passes before it make of it",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' writes 'd', which is read with "
                           "frame=\"previous\": a skipped frame could not leave what running it leaves there, so the effect "
                           "cannot have a source",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' reads 'd' with frame=\"previous\": the effect "
                           "cannot have a source",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' writes 'd', which pass 'p5' outside the effect "
                           "writes too: a skipped effect's targets are cleared to zero, which would lose what 'p5' wrote",
              }));
}

TEST(Validation, AnEffectsSourceIsCompleteBeforeItsFirstPass) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <effect name=\"e\" passes=\"p\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"S\" target=\"src\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"more\" target=\"src\">", kPlainShader, "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <effect name=\"e\">: pass 'more' writes the source 'src' after pass 'p' "
                                        "of the effect: whether the effect contributes is decided before its first pass, so "
                                        "the source must be complete by then"}));
}

// <effect gate>: counted in place of the source, so it must exist, differ from the source, be
// written outside the effect and be complete before the effect's first pass.
TEST(Validation, AnEffectsGateIsWrittenBeforeTheEffectByPassesOutsideIt) {
    test::ScratchDir dir;
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto reading = [&](const std::string& pass, const std::string& target) {
        return "  <pass name=\"" + pass + "\" target=\"" + target + "\">\n    <sampler name=\"S\" target=\"src\"/>\n" + sampling +
               "\n  </pass>";
    };
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"g\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g2\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g3\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g4\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <target name=\"c\" format=\"rgba8\"/>",
                           "  <target name=\"d\" format=\"rgba8\"/>",
                           "  <target name=\"e\" format=\"rgba8\"/>",
                           "  <target name=\"f\" format=\"rgba8\"/>",
                           "  <effect name=\"good\" passes=\"pa\" source=\"src\" gate=\"g\"/>",
                           "  <effect name=\"unknown\" passes=\"pb\" source=\"src\" gate=\"nope\"/>",
                           "  <effect name=\"same\" passes=\"pc\" source=\"src\" gate=\"src\"/>",
                           "  <effect name=\"inside\" passes=\"pd inner\" source=\"src\" gate=\"g2\"/>",
                           "  <effect name=\"late\" passes=\"pe\" source=\"src\" gate=\"g3\"/>",
                           "  <effect name=\"unwritten\" passes=\"pf\" source=\"src\" gate=\"g4\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"bound\" target=\"g\">", kPlainShader, "  </pass>",
                           reading("pa", "a"), reading("pb", "b"), reading("pc", "c"), reading("pd", "d"),
                           "  <pass name=\"inner\" target=\"g2\">", kPlainShader, "  </pass>",
                           reading("pe", "e"),
                           "  <pass name=\"after\" target=\"g3\">", kPlainShader, "  </pass>",
                           reading("pf", "f"),
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":14: error: <effect name=\"unknown\">: gate: no render target 'nope' (it has: src, g, g2, g3, g4, a, b, "
                           "c, d, e, f; the output is 'output')",
                  l.path + ":15: error: <effect name=\"same\">: gate 'src' is the source itself: leave 'gate' out to count the source",
                  l.path + ":16: error: <effect name=\"inside\">: gate 'g2' is written by pass 'inner' of the effect itself; the "
                           "gate is written before the effect, by passes outside it",
                  l.path + ":17: error: <effect name=\"late\">: pass 'after' writes the gate 'g3' after pass 'pe' of the effect: "
                           "whether the effect contributes is decided before its first pass, so the gate must be complete by then",
                  l.path + ":18: error: <effect name=\"unwritten\">: no pass writes the gate 'g4' before the effect",
              }));
}

// hdr_lighting's bloom and star start from 'bright' through star_source, a blur of it outside
// both: reading through a pass before the effect counts; through last frame's contents it does not.
TEST(Validation, AnEffectMayReadItsSourceThroughPassesBeforeIt) {
    test::ScratchDir dir;
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"blurred\" format=\"rgba8\"/>",
                           "  <target name=\"late\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <effect name=\"through\" passes=\"pa\" source=\"src\"/>",
                           "  <effect name=\"history\" passes=\"pb\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"blur\" target=\"blurred\">", "    <sampler name=\"S\" target=\"src\"/>", sampling, "  </pass>",
                           "  <pass name=\"pa\" target=\"a\">", "    <sampler name=\"S\" target=\"blurred\"/>", sampling, "  </pass>",
                           "  <pass name=\"remember\" target=\"late\">",
                           "    <sampler name=\"S\" target=\"src\" frame=\"previous\"/>", sampling, "  </pass>",
                           "  <pass name=\"pb\" target=\"b\">", "    <sampler name=\"S\" target=\"late\"/>", sampling, "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":8: error: <effect name=\"history\">: no pass of the effect reads its source "
                                        "'src', directly or through what passes before it make of it"}));
}

TEST(Validation, ACycleOfPassesIsAnErrorNamingThem) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <pass name=\"pa\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"b\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"pb\" target=\"b\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <sampler name=\"s\">: passes form a cycle: 'pa' reads 'b' from 'pb', "
                                        "'pb' reads 'a' from 'pa'; read one of them with frame=\"previous\" to take last "
                                        "frame's contents"}));
}

}  // namespace rmfx
