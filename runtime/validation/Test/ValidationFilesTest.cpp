// Validation of the files a workspace names: images, models and shaders that must exist, and
// #include: not found, cycles, and the folder includes may not leave.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationFiles, MissingImageFiles) {
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

TEST(ValidationFiles, MissingModelFile) {
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

TEST(ValidationFiles, MissingShaderFile) {
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

TEST(ValidationFiles, NoFragmentShader) {
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

TEST(ValidationFiles, IncludeNotFound) {
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

TEST(ValidationFiles, IncludeCycleNamesTheChain) {
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

TEST(ValidationFiles, ShaderFileIncludingItselfIsACycle) {
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

TEST(ValidationFiles, IncludeOutsideTheWorkspaceFolder) {
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
TEST(ValidationFiles, IncludeRootWidensTheIncludeFolderToAnAncestor) {
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

}  // namespace
}  // namespace rmfx
