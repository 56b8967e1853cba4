#include "frontend/shader/ShaderPreprocessor.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/TestSupport.h"

namespace rmfx {

namespace {

using Lines = std::vector<std::string>;
using test::lines;

// "file:line" of every line of the output, for compact comparisons.
Lines origins(const PreprocessedShader& shader) {
    Lines out;
    for (const SourceLocation& l : shader.lineOrigins) out.push_back(l.file + ":" + std::to_string(l.line));
    return out;
}

ShaderInput inputFor(const test::ScratchDir& dir, const std::string& code) {
    ShaderInput input;
    input.code = code;
    input.start = {"main.frag", 1};
    input.folder = input.root = dir.path();
    return input;
}

std::vector<std::string> formatted(const Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) out.push_back(d.format());
    return out;
}

}  // namespace

TEST(ShaderPreprocessor, LineMapThroughNestedIncludes) {
    test::ScratchDir dir;
    const std::string a = dir.write("a.glsl", lines({"#pragma once", "#include \"lib/b.glsl\"", "float a;"})).string();
    const std::string b = dir.write("lib/b.glsl", lines({"// b", "float b;"})).string();
    ShaderInput input = inputFor(dir, lines({"#version 330 core", "#include \"a.glsl\"", "void main() {}"}));
    input.defines = {"FOO 1", "BAR"};
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(formatted(d), Lines{});
    EXPECT_EQ(out.code, lines({"#version 330 core", "#define FOO 1", "#define BAR", "", "", "// b", "float b;",
                               "float a;", "void main() {}"}));
    EXPECT_EQ(origins(out), (Lines{"main.frag:1", "main.frag:1", "main.frag:1", "main.frag:1", a + ":1", b + ":1",
                                   b + ":2", a + ":3", "main.frag:3"}));
    EXPECT_EQ(out.files, (std::vector<std::filesystem::path>{a, b}));
    EXPECT_EQ(out.origin(7).file, b);
    EXPECT_EQ(out.origin(7).line, 2);
    // Out of range lines clamp to the first and last.
    EXPECT_EQ(out.origin(0).line, 1);
    EXPECT_EQ(out.origin(100).file, "main.frag");
    EXPECT_EQ(out.origin(100).line, 3);
}

TEST(ShaderPreprocessor, IncludesResolveNextToTheIncludingFileThenAtTheRoot) {
    test::ScratchDir dir;
    const std::string inner = dir.write("lib/inner.glsl", "float inner;\n").string();
    const std::string shared = dir.write("shared.glsl", "float shared;\n").string();
    dir.write("lib/outer.glsl", lines({"#include \"inner.glsl\"", "#include \"shared.glsl\""}));
    ShaderInput input = inputFor(dir, "#include \"lib/outer.glsl\"\n");
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(formatted(d), Lines{});
    EXPECT_EQ(out.code, lines({"#version 450 core", "float inner;", "float shared;"}));
    EXPECT_EQ(origins(out), (Lines{"main.frag:1", inner + ":1", shared + ":1"}));
}

TEST(ShaderPreprocessor, PragmaOnceIncludesAFileOnce) {
    test::ScratchDir dir;
    const std::string once = dir.write("once.glsl", lines({"#pragma once", "float once;"})).string();
    const std::string twice = dir.write("twice.glsl", "float twice;\n").string();
    ShaderInput input = inputFor(dir, lines({"#version 450", "#include \"once.glsl\"", "#include \"twice.glsl\"",
                                             "#include \"once.glsl\"", "#include \"twice.glsl\""}));
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(formatted(d), Lines{});
    EXPECT_EQ(out.code, lines({"#version 450", "", "", "float once;", "float twice;", "", "float twice;"}));
    EXPECT_EQ(origins(out), (Lines{"main.frag:1", "main.frag:1", once + ":1", once + ":2", twice + ":1",
                                   "main.frag:4", twice + ":1"}));
    EXPECT_EQ(out.files.size(), 3u);  // once.glsl is read once
}

TEST(ShaderPreprocessor, MissingVersionGetsTheDefaultAndDefinesFollowIt) {
    test::ScratchDir dir;
    ShaderInput input = inputFor(dir, lines({"out vec4 c;", "void main() {}"}));
    input.start = {"fx.xml", 20};  // inline code starting on line 20 of a workspace
    input.defines = {"HDR 1"};
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(out.code, lines({"#version 450 core", "#define HDR 1", "out vec4 c;", "void main() {}"}));
    EXPECT_EQ(origins(out), (Lines{"fx.xml:20", "fx.xml:20", "fx.xml:20", "fx.xml:21"}));
}

TEST(ShaderPreprocessor, VersionAfterCommentsMovesFirst) {
    test::ScratchDir dir;
    ShaderInput input = inputFor(dir, lines({"// a comment", "", "#version 330", "float x;"}));
    input.defines = {"A"};
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(out.code, lines({"#version 330", "#define A", "// a comment", "", "", "float x;"}));
    EXPECT_EQ(origins(out), (Lines{"main.frag:3", "main.frag:3", "main.frag:1", "main.frag:2", "main.frag:3",
                                   "main.frag:4"}));
}

TEST(ShaderPreprocessor, VersionFromAnIncludedFile) {
    test::ScratchDir dir;
    const std::string header = dir.write("header.glsl", lines({"#version 410 core", "precision highp float;"})).string();
    ShaderInput input = inputFor(dir, lines({"#include \"header.glsl\"", "void main() {}"}));
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(out.code, lines({"#version 410 core", "", "precision highp float;", "void main() {}"}));
    EXPECT_EQ(origins(out), (Lines{header + ":1", header + ":1", header + ":2", "main.frag:2"}));
}

TEST(ShaderPreprocessor, SnippetsComeFirstAndKeepWorkspaceLines) {
    test::ScratchDir dir;
    dir.write("sky.glsl", "float fromFile;\n");
    std::vector<CodeSnippet> snippets{{"sky.glsl", "\nfloat fromSnippet;\n", 16, {"fx.xml", 16}}};
    ShaderInput input = inputFor(dir, lines({"#version 450 core", "#include \"sky.glsl\"", "void main() {}"}));
    input.start = {"fx.xml", 40};
    input.snippets = &snippets;
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(formatted(d), Lines{});
    EXPECT_EQ(out.code, lines({"#version 450 core", "", "", "float fromSnippet;", "void main() {}"}));
    EXPECT_EQ(origins(out), (Lines{"fx.xml:40", "fx.xml:40", "fx.xml:16", "fx.xml:17", "fx.xml:42"}));
    EXPECT_TRUE(out.files.empty());
}

TEST(ShaderPreprocessor, IncludeErrors) {
    test::ScratchDir dir;
    dir.write("ws/self.glsl", lines({"float s;", "#include \"self.glsl\""}));
    dir.write("outside.glsl", "float o;\n");
    ShaderInput input = inputFor(dir, lines({
                                          "#include <angle.glsl>",
                                          "#include \"nowhere.glsl\"",
                                          "#include \"self.glsl\"",
                                          "#include \"../outside.glsl\"",
                                      }));
    input.folder = input.root = dir.path() / "ws";
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    const std::string root = (dir.path() / "ws").string();
    EXPECT_EQ(formatted(d), (Lines{
                                "main.frag:1: error: #include: expected #include \"file\"",
                                "main.frag:2: error: #include: cannot find \"nowhere.glsl\" (looked in " + root + ")",
                                root + "/self.glsl:2: error: #include: include cycle: \"self.glsl\" → \"self.glsl\"",
                                "main.frag:4: error: #include: \"../outside.glsl\" lies outside the workspace folder " +
                                    root,
                            }));
    // Failed includes keep one empty line each, so later lines stay mapped.
    EXPECT_EQ(out.code, lines({"#version 450 core", "", "", "float s;", "", ""}));
    EXPECT_EQ(origins(out), (Lines{"main.frag:1", "main.frag:1", "main.frag:2", root + "/self.glsl:1",
                                   root + "/self.glsl:2", "main.frag:4"}));
}

TEST(ShaderPreprocessor, SnippetCycle) {
    test::ScratchDir dir;
    std::vector<CodeSnippet> snippets{{"a", "#include \"b\"\n", 5, {"fx.xml", 5}},
                                      {"b", "\n#include \"a\"\n", 8, {"fx.xml", 8}}};
    ShaderInput input = inputFor(dir, "#include \"a\"\n");
    input.snippets = &snippets;
    Diagnostics d;
    preprocessShader(input, d);
    EXPECT_EQ(formatted(d), (Lines{"fx.xml:9: error: #include: include cycle: \"a\" → \"b\" → \"a\""}));
}

// ---- compiler logs ----

namespace {

// A shader whose line 2 comes from common.glsl:7 and line 3 from fx.xml:30.
PreprocessedShader mappedShader() {
    PreprocessedShader s;
    s.code = "#version 450 core\nfloat helper();\nvoid main() {}\n";
    s.lineOrigins = {{"fx.xml", 28}, {"common.glsl", 7}, {"fx.xml", 30}};
    return s;
}

const SourceLocation kFallback{"fx.xml", 27};

}  // namespace

TEST(ShaderPreprocessor, MapsGlslangLog) {
    Diagnostics d = mapCompilerLog(lines({
                                       "ERROR: 0:2: 'helper' : no matching overloaded function found ",  // glslang's trailing space
                                       "WARNING: 0:3: 'x' : unused",
                                       "ERROR: 0:3: '' : compilation terminated",
                                       "ERROR: 2 compilation errors.  No code generated.",
                                   }),
                                   mappedShader(), kFallback, "<pass name=\"p\">");
    EXPECT_EQ(formatted(d),
              (Lines{"common.glsl:7: error: <pass name=\"p\">: 'helper' : no matching overloaded function found",
                     "fx.xml:30: warning: <pass name=\"p\">: 'x' : unused",
                     "fx.xml:30: error: <pass name=\"p\">: '' : compilation terminated"}));
}

TEST(ShaderPreprocessor, MapsMesaLog) {
    Diagnostics d = mapCompilerLog("0:2(12): error: `undefinedThing' undeclared\n0:3(1): warning: unused variable\n",
                                   mappedShader(), kFallback, "<pass name=\"p\">");
    EXPECT_EQ(formatted(d), (Lines{"common.glsl:7: error: <pass name=\"p\">: `undefinedThing' undeclared",
                                   "fx.xml:30: warning: <pass name=\"p\">: unused variable"}));
}

TEST(ShaderPreprocessor, MapsNvidiaLog) {
    Diagnostics d = mapCompilerLog("0(2) : error C1008: undefined variable \"undefinedThing\"\r\n"
                                   "0(3) : warning C7022: unrecognized profile specifier\r\n",
                                   mappedShader(), kFallback, "<pass name=\"p\">");
    EXPECT_EQ(formatted(d),
              (Lines{"common.glsl:7: error: <pass name=\"p\">: C1008: undefined variable \"undefinedThing\"",
                     "fx.xml:30: warning: <pass name=\"p\">: C7022: unrecognized profile specifier"}));
}

TEST(ShaderPreprocessor, UnrecognisedLogLinesFallBackToTheShader) {
    Diagnostics d = mapCompilerLog("\nLinking failed: something odd\nERROR: Linking fragment stage: missing main\n",
                                   mappedShader(), kFallback, "<pass name=\"p\">");
    EXPECT_EQ(formatted(d), (Lines{"fx.xml:27: error: <pass name=\"p\">: Linking failed: something odd",
                                   "fx.xml:27: error: <pass name=\"p\">: Linking fragment stage: missing main"}));
}

}  // namespace rmfx

namespace rmfx {

// Snippets s0..s{depth-1}, each including the next twice: 2^depth includes from 2 * depth lines.
static std::vector<CodeSnippet> doublingSnippets(int depth) {
    std::vector<CodeSnippet> snippets;
    for (int i = 0; i < depth; ++i) {
        std::string next = "#include \"s" + std::to_string(i + 1) + "\"";
        snippets.push_back({"s" + std::to_string(i), lines({next, next}), 10 + 2 * i, {"w.xml", 9 + 2 * i}});
    }
    snippets.push_back({"s" + std::to_string(depth), "float x;", 10 + 2 * depth, {"w.xml", 9 + 2 * depth}});
    return snippets;
}

TEST(ShaderPreprocessor, IncludesStopAtOneMebibyteOfCode) {
    test::ScratchDir dir;
    // 8 levels of doubling: 256 copies of a 32 KiB line, 8 MiB in full; the expansion stops at 1 MiB.
    std::vector<CodeSnippet> snippets = doublingSnippets(8);
    snippets.back().code = "// " + std::string(32 * 1024, 'y');
    ShaderInput input = inputFor(dir, lines({"#include \"s0\"", "void main() {}"}));
    input.snippets = &snippets;
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("or 1 MiB through its includes"), std::string::npos) << d[0].message;
    const auto copies = std::count(out.code.begin(), out.code.end(), 'y') / (32 * 1024);
    EXPECT_EQ(copies, 31);  // 32 would pass 1 MiB with the lines around them
    EXPECT_LE(out.code.size(), size_t(1) << 20);
    EXPECT_EQ(static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n')), out.lineOrigins.size());
}

TEST(ShaderPreprocessor, IncludesThatGrowTheShaderExponentiallyStopWithOneError) {
    test::ScratchDir dir;
    ShaderInput input = inputFor(dir, lines({"#include \"s0\"", "void main() {}"}));
    // 2^10 = 1024 copies expand in full ...
    std::vector<CodeSnippet> small = doublingSnippets(10);
    input.snippets = &small;
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    EXPECT_EQ(formatted(d), Lines{});
    EXPECT_EQ(std::count(out.code.begin(), out.code.end(), 'x'), 1024);
    // ... 2^30 would be 2^30 lines: the expansion stops at 4096 includes, with one error.
    std::vector<CodeSnippet> huge = doublingSnippets(30);
    input.snippets = &huge;
    d.clear();
    out = preprocessShader(input, d);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("grows past 4096 includes, 65536 lines or 1 MiB through its includes"), std::string::npos) << d[0].message;
    EXPECT_EQ(d[0].where.file, "w.xml");  // in a snippet
    EXPECT_LE(std::count(out.code.begin(), out.code.end(), 'x'), 4096);
    EXPECT_EQ(static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n')), out.lineOrigins.size());
}

TEST(ShaderPreprocessor, AnIncludeNameTheFileSystemRefusesIsAnErrorOnItsLine) {
    test::ScratchDir dir;
    // 300 bytes is past NAME_MAX (255): looking it up fails with ENAMETOOLONG, which must end as an
    // error naming the include (it threw filesystem_error out of preprocessShader).
    std::string name(300, 'a');
    ShaderInput input = inputFor(dir, lines({"#version 450 core", "#include \"" + name + "\"", "void main() {}"}));
    Diagnostics d;
    PreprocessedShader out = preprocessShader(input, d);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].where.file, "main.frag");
    EXPECT_EQ(d[0].where.line, 2);
    EXPECT_EQ(d[0].severity, Diagnostic::Severity::Error);
    EXPECT_NE(d[0].message.find("\"" + name.substr(0, 64)), std::string::npos) << d[0].message;  // names it
}

TEST(ShaderPreprocessor, IncludeLinesOfAnyLengthAreParsedWithoutRecursion) {
    test::ScratchDir dir;
    // libstdc++'s std::regex overflowed the stack on an include line of some 40000 bytes.
    std::string name = std::string(100000, 'b') + "/x.glsl";
    ShaderInput input = inputFor(dir, lines({"#include \"\"", "# include \"a.glsl\" x", "#include \"" + name + "\"  // long"}));
    Diagnostics d;
    preprocessShader(input, d);
    ASSERT_EQ(d.size(), 3u) << formatAll(d);
    EXPECT_EQ(d[0].message, "expected #include \"file\"");  // an empty name
    EXPECT_EQ(d[1].message, "expected #include \"file\"");  // text after the name
    EXPECT_EQ(d[2].where.line, 3);  // read, then refused by the file system (a component of 100000 bytes)
    EXPECT_NE(d[2].message.find("\"" + name.substr(0, 64)), std::string::npos) << d[2].message.substr(0, 200);
}

TEST(ShaderPreprocessor, CompilerLogLinesPastIntOrVeryLongMapWithoutThrowing) {
    test::ScratchDir dir;
    ShaderInput input = inputFor(dir, lines({"float a;", "void main() {}"}));
    Diagnostics none;
    PreprocessedShader shader = preprocessShader(input, none);
    std::string identifier(50000, 'c');
    Diagnostics d = mapCompilerLog(lines({"ERROR: 0:99999999999: 'x' : undeclared identifier",
                                          "ERROR: 0:2: '" + identifier + "' : undeclared identifier"}),
                                   shader, {"main.frag", 1}, "<shader>");
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].where.line, 2);  // past the end: the last line
    EXPECT_EQ(d[0].message, "'x' : undeclared identifier");
    EXPECT_EQ(d[1].where.line, 1);  // line 2 of the code is the user's line 1 (#version went first)
    EXPECT_EQ(d[1].message.size(), 4096 - std::string("ERROR: 0:2: ").size() + std::string("…").size());
}

TEST(ShaderPreprocessor, OpeningVersionReadsTheFirstLineOnly) {
    const std::string code = "#version 330 core\nout vec4 c;\n";
    std::optional<OpeningVersion> v = openingVersion(code);
    ASSERT_TRUE(v);
    EXPECT_EQ(v->number, 330);
    EXPECT_FALSE(v->es);
    EXPECT_EQ(code.substr(v->end), "out vec4 c;\n");
    v = openingVersion("  # version 300 es");
    ASSERT_TRUE(v);
    EXPECT_EQ(v->number, 300);
    EXPECT_TRUE(v->es);
    EXPECT_EQ(v->end, 18u);
    EXPECT_FALSE(openingVersion("void main() {}\n#version 450\n"));
    EXPECT_FALSE(openingVersion(""));
}

}  // namespace rmfx
