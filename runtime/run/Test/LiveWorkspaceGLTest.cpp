// LiveWorkspace: hot reload of a workspace in a scratch folder, headless. Each test edits a file
// the way a user would (in place, or written to a temporary file and renamed over it), polls until
// the reload happened (at most 5 s, every 5 ms; nothing here is timed), renders a frame and reads
// the value the edited file now produces.
//
// The workspace: passes a and b include common.glsl; c samples a 1x1 float texture; "out" writes
// the variable Gain to the output. Each pass writes a constant, so every expected value is exact.

#include <chrono>
#include <fstream>
#include <ostream>
#include <thread>

#include <gtest/gtest.h>
#include <glm/vec4.hpp>

#include "io/image/ImageIO.h"
#include "run/LiveWorkspace.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace glm {
// Readable gtest messages for the pixels compared below.
static void PrintTo(const vec4& v, std::ostream* os) { *os << "(" << v.r << ", " << v.g << ", " << v.b << ", " << v.a << ")"; }
}  // namespace glm

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using Names = std::vector<std::string>;

// Line 9 is pass b's opening tag; the tests break and rename it.
const std::string workspaceXml = lines({
    R"(<workspace version="1" name="live" size="4x4">)",
    R"(  <float name="Gain" value="1"/>)",
    R"(  <camera yaw="30" pitch="15" distance="4"/>)",
    R"(  <texture name="Tex" file="tex.exr" mipmaps="false"/>)",
    R"(  <target name="ta" format="rgba32f" size="1x1"/>)",
    R"(  <target name="tb" format="rgba32f" size="1x1"/>)",
    R"(  <target name="tc" format="rgba32f" size="1x1"/>)",
    R"(  <pass name="a" target="ta"><shader stage="fragment" file="a.frag"/></pass>)",
    R"(  <pass name="b" target="tb"><shader stage="fragment" file="b.frag"/></pass>)",
    R"(  <pass name="c" target="tc"><sampler name="Tex" texture="Tex" filter="nearest"/>)",
    R"(    <shader stage="fragment" file="c.frag"/></pass>)",
    R"(  <pass name="out"><shader stage="fragment"><![CDATA[)",
    R"(uniform float Gain;)",
    R"(out vec4 color;)",
    R"(void main() { color = vec4(Gain, 0.0, 0.0, 1.0); })",
    R"(]]></shader></pass>)",
    R"(</workspace>)",
});

// Line 5 holds the constant; the tests change it and break it.
std::string aShader(const std::string& line5) {
    return lines({"#version 450 core", "#include \"common.glsl\"", "out vec4 color;", "void main() {", line5, "}"});
}
std::string aShader(double red) { return aShader("    color = vec4(" + glslFloat(red) + ", common_value(), 0.0, 1.0);"); }
std::string commonGlsl(double value) { return "float common_value() { return " + glslFloat(value) + "; }\n"; }
const std::string bShader = lines({"#version 450 core", "#include \"common.glsl\"", "out vec4 color;",
                                   "void main() { color = vec4(common_value() * 2.0, 0.0, 0.0, 1.0); }"});
const std::string cShader = lines({"#version 450 core", "uniform sampler2D Tex;", "out vec4 color;",
                                   "void main() { color = texelFetch(Tex, ivec2(0), 0); }"});

Image texel(glm::vec4 value) {
    Image image;
    image.width = image.height = 1;
    image.channels = 4;
    image.highDynamicRange = true;
    image.pixels = {value.r, value.g, value.b, value.a};
    return image;
}

// The way editors save: a temporary file beside the original, renamed over it (a new inode).
void saveAtomically(const fs::path& file, const std::string& text) {
    fs::path temporary = file.parent_path() / ("." + file.filename().string() + ".swp");
    std::ofstream(temporary, std::ios::binary) << text;
    fs::rename(temporary, file);
}
void saveInPlace(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

bool sameFile(const std::string& a, const fs::path& b) {
    std::error_code e;
    return fs::equivalent(a, b, e);
}

class LiveWorkspaceGLTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        dir_.write("ws.xml", workspaceXml);
        dir_.write("a.frag", aShader(0.25));
        dir_.write("b.frag", bShader);
        dir_.write("c.frag", cShader);
        dir_.write("common.glsl", commonGlsl(0.5));
        ASSERT_TRUE(writeImage(dir_ / "tex.exr", texel({0.125f, 0.25f, 0.375f, 0.5f})));
        auto opened = LiveWorkspace::open(dir_ / "ws.xml", {0, 0}, {});
        ASSERT_TRUE(opened) << formatAll(opened.diagnostics());
        live_ = std::move(*opened);
        ASSERT_EQ(pixel("ta"), glm::vec4(0.25f, 0.5f, 0.0f, 1.0f));
    }

    bool waitForReload() { return test::waitForReload(*live_); }

    // Renders a frame and reads pixel (0, 0) of a target.
    glm::vec4 pixel(const std::string& target) {
        Diagnostics frame = live_->executor().renderFrame({}).takeDiagnostics();
        EXPECT_FALSE(hasErrors(frame)) << formatAll(frame);
        Image image = readBack(live_->executor(), target);
        if (image.empty()) return glm::vec4(-1.0f);
        return {image.at(0, 0, 0), image.at(0, 0, 1), image.at(0, 0, 2), image.at(0, 0, 3)};
    }

    std::map<std::string, unsigned> programs() {
        std::map<std::string, unsigned> out;
        for (const char* pass : {"a", "b", "c", "out"}) out[pass] = live_->executor().passProgram(pass);
        return out;
    }

    // Whether some error is located at `file`:`line` (line 0: any line).
    bool hasErrorAt(const fs::path& file, int line) {
        for (const Diagnostic& d : live_->errors())
            if (d.severity == Diagnostic::Severity::Error && sameFile(d.where.file, file) && (line == 0 || d.where.line == line))
                return true;
        return false;
    }

    ScratchDir dir_;
    std::unique_ptr<LiveWorkspace> live_;
};

TEST_F(LiveWorkspaceGLTest, WatchesEveryFileTheWorkspaceReads) {
    std::vector<fs::path> expected;
    for (const char* f : {"ws.xml", "a.frag", "b.frag", "c.frag", "common.glsl", "tex.exr"})
        expected.push_back(fs::weakly_canonical(dir_ / f));
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(live_->watchedFiles(), expected);
    EXPECT_TRUE(live_->errors().empty());
    EXPECT_FALSE(live_->poll());  // nothing changed
}

TEST_F(LiveWorkspaceGLTest, EditedShaderRecompilesOnlyItsPass) {
    auto before = programs();
    saveInPlace(dir_ / "a.frag", aShader(0.75));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(live_->lastReload().recompiledPasses, Names{"a"});
    EXPECT_FALSE(live_->lastReload().workspaceRebuilt);
    auto after = programs();
    EXPECT_NE(after["a"], before["a"]);
    EXPECT_EQ(after["b"], before["b"]);
    EXPECT_EQ(after["c"], before["c"]);
    EXPECT_EQ(after["out"], before["out"]);
    EXPECT_EQ(pixel("ta"), glm::vec4(0.75f, 0.5f, 0.0f, 1.0f));
    EXPECT_GT(live_->lastReloadMilliseconds(), 0.0);
}

TEST_F(LiveWorkspaceGLTest, AtomicSaveByRenameIsSeen) {
    saveAtomically(dir_ / "a.frag", aShader(1.5));
    ASSERT_TRUE(waitForReload());
    EXPECT_EQ(live_->lastReload().recompiledPasses, Names{"a"});
    EXPECT_EQ(pixel("ta"), glm::vec4(1.5f, 0.5f, 0.0f, 1.0f));
    saveAtomically(dir_ / "a.frag", aShader(2.5));  // the folder watch survives the new inode
    ASSERT_TRUE(waitForReload());
    EXPECT_EQ(pixel("ta"), glm::vec4(2.5f, 0.5f, 0.0f, 1.0f));
}

TEST_F(LiveWorkspaceGLTest, BrokenShaderKeepsTheLastGoodBuildAndRecovers) {
    pixel("ta");
    auto before = programs();
    // (b) a syntax error on line 5 of a.frag: a missing comma
    saveInPlace(dir_ / "a.frag", aShader("    color = vec4(0.875 common_value(), 0.0, 1.0);"));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->lastReload().failed);
    EXPECT_TRUE(hasErrorAt(dir_ / "a.frag", 5)) << formatAll(live_->errors());
    EXPECT_EQ(programs(), before);  // nothing swapped in
    // The last frame is still there, and the old program renders on.
    Image last = readBack(live_->executor(), "ta");
    ASSERT_FALSE(last.empty());
    EXPECT_EQ(last.at(0, 0, 0), 0.25f);
    EXPECT_EQ(pixel("ta"), glm::vec4(0.25f, 0.5f, 0.0f, 1.0f));

    // A second broken save is handled like the first: the new error, on line 4 this time.
    saveInPlace(dir_ / "a.frag", lines({"#version 450 core", "#include \"common.glsl\"", "out vec4 color;",
                                        "void main() { color = undefined_name; }"}));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(hasErrorAt(dir_ / "a.frag", 4)) << formatAll(live_->errors());
    EXPECT_FALSE(hasErrorAt(dir_ / "a.frag", 5)) << formatAll(live_->errors());

    // (c) fixed: recovers without a restart
    saveAtomically(dir_ / "a.frag", aShader(0.875));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_FALSE(live_->lastReload().failed);
    EXPECT_EQ(live_->lastReload().recompiledPasses, Names{"a"});
    EXPECT_EQ(pixel("ta"), glm::vec4(0.875f, 0.5f, 0.0f, 1.0f));
}

TEST_F(LiveWorkspaceGLTest, EditedIncludeRecompilesThePassesThatIncludeIt) {
    auto before = programs();
    saveInPlace(dir_ / "common.glsl", commonGlsl(0.375));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(live_->lastReload().recompiledPasses, (Names{"a", "b"}));
    auto after = programs();
    EXPECT_NE(after["a"], before["a"]);
    EXPECT_NE(after["b"], before["b"]);
    EXPECT_EQ(after["c"], before["c"]);
    EXPECT_EQ(pixel("ta"), glm::vec4(0.25f, 0.375f, 0.0f, 1.0f));
    EXPECT_EQ(pixel("tb"), glm::vec4(0.75f, 0.0f, 0.0f, 1.0f));
}

TEST_F(LiveWorkspaceGLTest, BrokenIncludeKeepsEveryPassThatIncludesIt) {
    auto before = programs();
    saveInPlace(dir_ / "common.glsl", "float common_value() { return 0.5 }\n");  // line 1: no ';'
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(hasErrorAt(dir_ / "common.glsl", 1)) << formatAll(live_->errors());
    EXPECT_EQ(programs(), before);
    EXPECT_EQ(pixel("tb"), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    saveInPlace(dir_ / "common.glsl", commonGlsl(0.0625));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tb"), glm::vec4(0.125f, 0.0f, 0.0f, 1.0f));
}

// One change, two passes: one compiles, the other does not. Neither is swapped in, and the
// include's new text reaches both once the other is fixed, even though only b.frag changed then.
TEST_F(LiveWorkspaceGLTest, PassesOfOneChangeAreSwappedInAllOrNothing) {
    saveInPlace(dir_ / "b.frag", lines({"#version 450 core", "#include \"common.glsl\"", "out vec4 color;",
                                        "float helper() { return 1.0; }",
                                        "void main() { color = vec4(common_value() * 2.0, helper(), 0.0, 1.0); }"}));
    ASSERT_TRUE(waitForReload());
    ASSERT_EQ(live_->lastReload().recompiledPasses, Names{"b"});
    auto before = programs();
    // helper() is now defined twice in b (line 4 of b.frag, line 2 of common.glsl); a is fine.
    saveInPlace(dir_ / "common.glsl", "float common_value() { return 0.125; }\nfloat helper() { return 2.0; }\n");
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->lastReload().failed);
    EXPECT_TRUE(live_->lastReload().recompiledPasses.empty());
    EXPECT_FALSE(live_->errors().empty());
    EXPECT_EQ(programs(), before);
    EXPECT_EQ(pixel("ta"), glm::vec4(0.25f, 0.5f, 0.0f, 1.0f));
    saveInPlace(dir_ / "b.frag", bShader);
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(live_->lastReload().recompiledPasses, (Names{"a", "b"}));
    EXPECT_EQ(pixel("ta"), glm::vec4(0.25f, 0.125f, 0.0f, 1.0f));
    EXPECT_EQ(pixel("tb"), glm::vec4(0.25f, 0.0f, 0.0f, 1.0f));
}

TEST_F(LiveWorkspaceGLTest, ShaderThatIncludesAFileNotWrittenYetRecoversWhenItAppears) {
    saveInPlace(dir_ / "c.frag", lines({"#version 450 core", "#include \"later.glsl\"", "out vec4 color;",
                                        "void main() { color = vec4(later_value()); }"}));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(hasErrorAt(dir_ / "c.frag", 2)) << formatAll(live_->errors());
    dir_.write("later.glsl", "float later_value() { return 0.5; }\n");
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tc"), glm::vec4(0.5f));
    // and is watched from now on
    saveInPlace(dir_ / "later.glsl", "float later_value() { return 0.25; }\n");
    ASSERT_TRUE(waitForReload());
    EXPECT_EQ(live_->lastReload().recompiledPasses, Names{"c"});
    EXPECT_EQ(pixel("tc"), glm::vec4(0.25f));
}

TEST_F(LiveWorkspaceGLTest, ReplacedTextureReloadsOnlyThatTexture) {
    auto programsBefore = programs();
    unsigned textureBefore = live_->executor().textureObject("Tex");
    EXPECT_EQ(pixel("tc"), glm::vec4(0.125f, 0.25f, 0.375f, 0.5f));
    // (e) written to a temporary file and renamed over the original
    fs::path temporary = dir_ / "tex.tmp.exr";
    ASSERT_TRUE(writeImage(temporary, texel({0.75f, 1.5f, 3.0f, 6.0f})));
    fs::rename(temporary, dir_ / "tex.exr");
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(live_->lastReload().reloadedTextures, Names{"Tex"});
    EXPECT_TRUE(live_->lastReload().recompiledPasses.empty());
    EXPECT_EQ(programs(), programsBefore);
    EXPECT_NE(live_->executor().textureObject("Tex"), textureBefore);
    EXPECT_EQ(pixel("tc"), glm::vec4(0.75f, 1.5f, 3.0f, 6.0f));
}

TEST_F(LiveWorkspaceGLTest, WorkspaceReloadCopiesUnchangedTexturesAndReadsChangedOnes) {
    unsigned first = live_->executor().textureObject("Tex");
    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(value="1")", R"(value="2")"));
    ASSERT_TRUE(waitForReload());
    ASSERT_TRUE(live_->lastReload().workspaceRebuilt);
    EXPECT_NE(live_->executor().textureObject("Tex"), first);  // the new build's own copy
    EXPECT_EQ(pixel("tc"), glm::vec4(0.125f, 0.25f, 0.375f, 0.5f));
    // The image and the workspace file saved together: the image is read, not copied.
    ASSERT_TRUE(writeImage(dir_ / "tex.exr", texel({2.0f, 3.0f, 5.0f, 7.0f})));
    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(value="1")", R"(value="3")"));
    for (int i = 0; i < 1000 && live_->executor().variable("Gain")->asFloat() != 3.0f; ++i) {
        live_->poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tc"), glm::vec4(2.0f, 3.0f, 5.0f, 7.0f));
}

class LiveModelGLTest : public GlTest {};

// A model file rewritten on disk: its mesh is replaced, no program is recompiled. The pass draws
// the model's triangle straight in clip space, so which pixels it covers shows which mesh is drawn.
TEST_F(LiveModelGLTest, ReplacedModelReloadsItsMesh) {
    ScratchDir dir;
    const std::string wholeScreen = "v -1 -1 0\nv 3 -1 0\nv -1 3 0\nf 1 2 3\n";
    const std::string lowerLeft = "v -1 -1 0\nv 0 -1 0\nv -1 0 0\nf 1 2 3\n";
    dir.write("tri.obj", wholeScreen);
    dir.write("ws.xml", lines({
        R"(<workspace version="1" name="model" size="4x4">)",
        R"(  <output format="rgba32f" transform="none"/>)",
        R"(  <pass name="p"><clear color="0 0 0 0"/><draw file="tri.obj"/>)",
        R"(    <shader stage="vertex"><![CDATA[)",
        R"(layout(location = 0) in vec3 rm_Position;)",
        R"(void main() { gl_Position = vec4(rm_Position.xy, 0.0, 1.0); })",
        R"(]]></shader>)",
        R"(    <shader stage="fragment"><![CDATA[)",
        R"(out vec4 color;)",
        R"(void main() { color = vec4(1.0); })",
        R"(]]></shader></pass>)",
        R"(</workspace>)",
    }));
    auto opened = LiveWorkspace::open(dir / "ws.xml", {0, 0}, {});
    ASSERT_TRUE(opened) << formatAll(opened.diagnostics());
    std::unique_ptr<LiveWorkspace> live = std::move(*opened);
    auto render = [&] {
        EXPECT_FALSE(hasErrors(live->executor().renderFrame({}).takeDiagnostics()));
        return readBack(live->executor(), "output");
    };
    Image before = render();
    ASSERT_FALSE(before.empty());
    EXPECT_EQ(atGl(before, 0, 0, 0), 1.0f);
    EXPECT_EQ(atGl(before, 3, 3, 0), 1.0f);
    unsigned program = live->executor().passProgram("p");

    saveAtomically(dir / "tri.obj", lowerLeft);
    ASSERT_TRUE(waitForReload(*live));
    EXPECT_TRUE(live->errors().empty()) << formatAll(live->errors());
    EXPECT_EQ(live->lastReload().reloadedModels, Names{"tri.obj"});
    EXPECT_TRUE(live->lastReload().recompiledPasses.empty());
    EXPECT_EQ(live->executor().passProgram("p"), program);
    Image after = render();
    ASSERT_FALSE(after.empty());
    EXPECT_EQ(atGl(after, 0, 0, 0), 1.0f);  // pixel centre (0.5, 0.5) of 4: inside the small triangle
    EXPECT_EQ(atGl(after, 3, 3, 0), 0.0f);  // outside it
    EXPECT_EQ(atGl(after, 3, 0, 0), 0.0f);

    // A model file that cannot be read keeps the mesh drawn so far.
    saveInPlace(dir / "tri.obj", "this is no model\n");
    ASSERT_TRUE(waitForReload(*live));
    EXPECT_FALSE(live->errors().empty());
    EXPECT_EQ(atGl(render(), 0, 0, 0), 1.0f);
}

class TextureCopyGLTest : public GlTest {};

// createReusing copies a mipmapped cube map level by level: every level of every face renders
// exactly as from a build that read the files.
TEST_F(TextureCopyGLTest, CopiedCubeMapMatchesTheLoadedOne) {
    ScratchDir dir;
    const char* faces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int f = 0; f < 6; ++f) {
        Image image;
        image.width = image.height = 4;
        image.channels = 4;
        image.highDynamicRange = true;
        image.pixels.resize(64);
        for (int i = 0; i < 64; ++i) image.pixels[i] = static_cast<float>(f * 100 + i);
        ASSERT_TRUE(writeImage(dir / (std::string(faces[f]) + ".exr"), image));
    }
    std::string xml = lines({
        R"(<workspace version="1" name="cube" size="6x3">)",
        R"(  <cubemap name="Sky" mipmaps="true">)",
        R"(    <face side="+x" file="px.exr"/> <face side="-x" file="nx.exr"/>)",
        R"(    <face side="+y" file="py.exr"/> <face side="-y" file="ny.exr"/>)",
        R"(    <face side="+z" file="pz.exr"/> <face side="-z" file="nz.exr"/>)",
        R"(  </cubemap>)",
        R"(  <output format="rgba32f" transform="none"/>)",
        R"(  <pass name="p"><sampler name="Sky" texture="Sky" filter="nearest" mipmap="nearest"/>)",
        R"(    <shader stage="fragment"><![CDATA[)",
        R"(uniform samplerCube Sky;)",
        R"(out vec4 color;)",
        R"(void main() {)",
        R"(    ivec2 p = ivec2(gl_FragCoord.xy);)",
        R"(    vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));)",
        R"(    color = textureLod(Sky, axes[p.x] + vec3(0.3, 0.2, 0.1), float(p.y));)",
        R"(})",
        R"(]]></shader></pass>)",
        R"(</workspace>)",
    });
    auto ws = workspaceFromText(xml, dir.path());
    ASSERT_TRUE(ws);
    std::shared_ptr<const Workspace> shared = std::move(ws);
    auto loadedResult = GlExecutor::create(shared, {6, 3});
    ASSERT_TRUE(loadedResult) << formatAll(loadedResult.diagnostics());
    auto& loaded = *loadedResult;
    auto copiedResult = GlExecutor::createReusing(shared, {6, 3}, {}, *loaded, {"Sky"});
    ASSERT_TRUE(copiedResult) << formatAll(copiedResult.diagnostics());
    auto& copied = *copiedResult;
    EXPECT_NE(copied->textureObject("Sky"), loaded->textureObject("Sky"));
    auto nothingReused = GlExecutor::createReusing(shared, {6, 3}, {}, *loaded, {});
    ASSERT_TRUE(nothingReused) << formatAll(nothingReused.diagnostics());
    ASSERT_FALSE(hasErrors(loaded->renderFrame({}).takeDiagnostics()));
    ASSERT_FALSE(hasErrors(copied->renderFrame({}).takeDiagnostics()));
    Image expected = readBack(*loaded, "output"), actual = readBack(*copied, "output");
    ASSERT_EQ(expected.pixels.size(), 6u * 3u * 4u);
    EXPECT_EQ(actual.pixels, expected.pixels);
    // Each face and level gave its own value (a copy of level 0 only, or of one face, would differ).
    for (int x = 0; x < 6; ++x)
        for (int level = 0; level < 3; ++level) {
            EXPECT_GE(atGl(expected, x, level, 0), 100.0f * x) << x << " " << level;
            EXPECT_LT(atGl(expected, x, level, 0), 100.0f * x + 64.0f) << x << " " << level;
            if (level > 0) {
                EXPECT_NE(atGl(expected, x, level, 0), atGl(expected, x, level - 1, 0)) << x << " " << level;
            }
        }
}

TEST_F(LiveWorkspaceGLTest, UnreadableTextureKeepsTheOldOne) {
    unsigned textureBefore = live_->executor().textureObject("Tex");
    saveInPlace(dir_ / "tex.exr", "this is not an EXR file");
    ASSERT_TRUE(waitForReload());
    ASSERT_FALSE(live_->errors().empty());
    EXPECT_NE(live_->errors().front().message.find("Tex"), std::string::npos) << formatAll(live_->errors());
    EXPECT_EQ(live_->executor().textureObject("Tex"), textureBefore);
    EXPECT_EQ(pixel("tc"), glm::vec4(0.125f, 0.25f, 0.375f, 0.5f));
    ASSERT_TRUE(writeImage(dir_ / "tex.exr", texel({1.0f, 2.0f, 4.0f, 8.0f})));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tc"), glm::vec4(1.0f, 2.0f, 4.0f, 8.0f));
}

TEST_F(LiveWorkspaceGLTest, TweakedValueAndCameraSurviveAWorkspaceReload) {
    ASSERT_EQ(live_->setVariable("Gain", Value::ofFloat(3.0f)).error(), "");
    EXPECT_EQ(pixel("output").r, 3.0f);
    live_->executor().camera().orbit(20.0f, 10.0f);  // yaw 30 → 50, pitch 15 → 25
    // (f) a new default for Gain and a new pass
    std::string edited = replaced(workspaceXml, R"(<float name="Gain" value="1"/>)", R"(<float name="Gain" value="2"/>)");
    edited = replaced(edited, R"(  <pass name="out">)",
                      "  <target name=\"te\" format=\"rgba32f\" size=\"1x1\"/>\n"
                      "  <pass name=\"extra\" target=\"te\"><shader stage=\"fragment\" file=\"b.frag\"/></pass>\n"
                      "  <pass name=\"out\">");
    saveAtomically(dir_ / "ws.xml", edited);
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().workspaceRebuilt);
    ASSERT_NE(live_->workspace().findPass("extra"), nullptr);
    EXPECT_EQ(live_->workspace().findVariable("Gain")->value.asFloat(), 2.0f);  // the file's new default
    EXPECT_EQ(pixel("output").r, 3.0f);                                          // the tweak
    EXPECT_EQ(pixel("te"), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(live_->executor().camera().settings().yawDegrees, 50.0f);
    EXPECT_EQ(live_->executor().camera().settings().pitchDegrees, 25.0f);
    EXPECT_TRUE(live_->warnings().empty()) << formatAll(live_->warnings());

    // the reset goes to the new default
    live_->resetVariable("Gain");
    EXPECT_EQ(pixel("output").r, 2.0f);
    EXPECT_TRUE(live_->tweakedValues().empty());
}

TEST_F(LiveWorkspaceGLTest, EditedCameraElementIsTakenFromTheFile) {
    live_->executor().camera().orbit(20.0f, 10.0f);
    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(yaw="30")", R"(yaw="-45")"));
    ASSERT_TRUE(waitForReload());
    EXPECT_EQ(live_->executor().camera().settings().yawDegrees, -45.0f);
    EXPECT_EQ(live_->executor().camera().settings().pitchDegrees, 15.0f);
}

TEST_F(LiveWorkspaceGLTest, TweakOfAVariableThatChangedTypeIsDroppedWithAWarning) {
    ASSERT_EQ(live_->setVariable("Gain", Value::ofFloat(3.0f)).error(), "");
    std::string edited = replaced(workspaceXml, R"(<float name="Gain" value="1"/>)", R"(<int name="Gain" value="4"/>)");
    edited = replaced(edited, "uniform float Gain;", "uniform int Gain;");
    edited = replaced(edited, "vec4(Gain, 0.0", "vec4(float(Gain), 0.0");
    saveInPlace(dir_ / "ws.xml", edited);
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    ASSERT_EQ(live_->warnings().size(), 1u);
    EXPECT_EQ(live_->warnings()[0].element, "variable Gain");
    EXPECT_EQ(live_->warnings()[0].where.line, 2);
    EXPECT_TRUE(live_->tweakedValues().empty());
    EXPECT_EQ(pixel("output").r, 4.0f);
}

TEST_F(LiveWorkspaceGLTest, BrokenWorkspaceFileKeepsTheLastGoodBuildAndRecovers) {
    ASSERT_EQ(live_->setVariable("Gain", Value::ofFloat(3.0f)).error(), "");
    pixel("output");
    auto before = programs();
    // Line 9: pass b writes a target that does not exist.
    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(target="tb")", R"(target="nowhere")"));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->lastReload().failed);
    EXPECT_TRUE(hasErrorAt(dir_ / "ws.xml", 9)) << formatAll(live_->errors());
    EXPECT_EQ(programs(), before);
    EXPECT_EQ(pixel("output").r, 3.0f);

    // Malformed XML: the unclosed tag is reported by line too.
    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(<pass name="b" target="tb">)", R"(<pass name="b" target="tb")"));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(hasErrorAt(dir_ / "ws.xml", 0)) << formatAll(live_->errors());
    EXPECT_EQ(pixel("output").r, 3.0f);

    // A shader edited meanwhile still reaches the running build.
    saveInPlace(dir_ / "a.frag", aShader(0.5));
    ASSERT_TRUE(waitForReload());
    EXPECT_EQ(pixel("ta"), glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
    EXPECT_FALSE(live_->errors().empty());  // the workspace file is still broken

    saveInPlace(dir_ / "ws.xml", replaced(workspaceXml, R"(value="1")", R"(value="5")"));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().workspaceRebuilt);
    EXPECT_EQ(pixel("output").r, 3.0f);  // the tweak outlived the broken saves
    EXPECT_EQ(pixel("ta"), glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
}

TEST_F(LiveWorkspaceGLTest, DeletedFilesAreErrorsUntilTheyComeBack) {
    // (g) a shader
    fs::remove(dir_ / "c.frag");
    ASSERT_TRUE(waitForReload());
    ASSERT_FALSE(live_->errors().empty());
    EXPECT_NE(formatAll(live_->errors()).find("c.frag"), std::string::npos) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tc"), glm::vec4(0.125f, 0.25f, 0.375f, 0.5f));
    dir_.write("c.frag", lines({"#version 450 core", "out vec4 color;", "void main() { color = vec4(0.0625); }"}));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("tc"), glm::vec4(0.0625f));

    // the workspace file
    fs::rename(dir_ / "ws.xml", dir_ / "ws.xml.bak");
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(hasErrorAt(dir_ / "ws.xml", 0) || !live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_EQ(pixel("ta"), glm::vec4(0.25f, 0.5f, 0.0f, 1.0f));
    fs::rename(dir_ / "ws.xml.bak", dir_ / "ws.xml");
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().workspaceRebuilt);
}

TEST_F(LiveWorkspaceGLTest, FirstBuildFailureReturnsNothing) {
    ScratchDir other;
    other.write("ws.xml", workspaceXml);  // no shader files there
    auto opened = LiveWorkspace::open(other / "ws.xml", {0, 0}, {});
    EXPECT_FALSE(opened);
    const Diagnostics& diagnostics = opened.diagnostics();
    EXPECT_TRUE(hasErrors(diagnostics));
    EXPECT_NE(formatAll(diagnostics).find("a.frag"), std::string::npos) << formatAll(diagnostics);
}

TEST_F(LiveWorkspaceGLTest, OverridesActAsTheFileDefaults) {
    auto opened = LiveWorkspace::open(dir_ / "ws.xml", {2, 2}, {{"Gain", "7"}});
    ASSERT_TRUE(opened) << formatAll(opened.diagnostics());
    std::unique_ptr<LiveWorkspace> live = std::move(*opened);
    EXPECT_EQ(live->executor().viewport(), glm::ivec2(2, 2));
    EXPECT_EQ(live->executor().variable("Gain")->asFloat(), 7.0f);
    auto unknown = LiveWorkspace::open(dir_ / "ws.xml", {0, 0}, {{"Nope", "1"}});
    EXPECT_FALSE(unknown);
    EXPECT_NE(formatAll(unknown.diagnostics()).find("Nope"), std::string::npos);
}

TEST_F(LiveWorkspaceGLTest, NewViewportKeepsTweaks) {
    ASSERT_EQ(live_->setVariable("Gain", Value::ofFloat(3.0f)).error(), "");
    Result<void> resized = live_->setViewport({8, 2});
    EXPECT_TRUE(resized) << formatAll(resized.diagnostics());
    EXPECT_EQ(live_->executor().targetSize("output"), glm::ivec2(8, 2));
    EXPECT_EQ(pixel("output").r, 3.0f);
}

}  // namespace
}  // namespace rmfx::test
