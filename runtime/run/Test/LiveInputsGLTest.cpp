// LiveWorkspace with an input image (rmfx edit --input, a file dropped on the editor): the image
// sets the viewport, its file hot-reloads like a texture, and a new file can be given at any time.
// Headless; each test changes a file the way a user would and polls until the reload happened (at
// most 5 s; nothing here is timed).
//
// The workspace: the target "scene" is drawn as 9 everywhere unless the input "scene" replaces it;
// "out" writes scene × Gain. Every image holds values a half float stores exactly, so every
// expected value is exact.

#include <fstream>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "run/LiveWorkspace.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

const std::string workspaceXml = lines({
    R"(<workspace version="1" name="live_input" size="4x4">)",
    R"(  <float name="Gain" value="2"/>)",
    R"(  <target name="scene" format="rgba32f"/>)",
    R"(  <input name="scene" replaces="scene" description="your image"/>)",
    R"(  <pass name="draw" target="scene"><shader stage="fragment">)",
    R"(    out vec4 c; void main() { c = vec4(9.0); })",
    R"(  </shader></pass>)",
    R"(  <pass name="copy" target="scene"><sampler name="Image" texture="scene" filter="nearest"/><shader stage="fragment">)",
    R"(    uniform sampler2D Image; out vec4 c; void main() { c = texelFetch(Image, ivec2(gl_FragCoord.xy), 0); })",
    R"(  </shader></pass>)",
    R"(  <pass name="out"><sampler name="Scene" target="scene" filter="nearest"/><shader stage="fragment">)",
    R"(    uniform sampler2D Scene; uniform float Gain; out vec4 c;)",
    R"(    void main() { c = texelFetch(Scene, ivec2(gl_FragCoord.xy), 0) * Gain; })",
    R"(  </shader></pass>)",
    R"(</workspace>)",
});

// A w x h image whose pixel (x, y) (row 0 at the top) is (x, y, base, 1) / 8 + base.
Image pattern(int w, int h, float base) {
    Image image = blankHdrImage(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &image.pixels[(static_cast<size_t>(y) * w + x) * 4];
            p[0] = base + x / 8.0f;
            p[1] = base + y / 8.0f;
            p[2] = base;
            p[3] = 1.0f;
        }
    return image;
}

// Written beside and renamed over the file, as editors and renderers save.
void saveAtomically(const fs::path& file, const Image& image) {
    fs::path temporary = file.parent_path() / ("tmp." + file.filename().string());
    ASSERT_TRUE(writeImage(temporary, image));
    fs::rename(temporary, file);
}

class LiveInputsGLTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        dir_.write("ws.xml", workspaceXml);
        ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "shot.exr", pattern(3, 2, 0.5f)));
        auto opened = LiveWorkspace::open(dir_ / "ws.xml", {0, 0}, {}, {}, {parseInputArgument((dir_ / "shot.exr").string())});
        ASSERT_TRUE(opened) << formatAll(opened.diagnostics());
        live_ = std::move(*opened);
    }

    bool waitForReload() { return test::waitForReload(*live_); }

    // Renders a frame and checks that the output is `image` × the gain, pixel for pixel.
    void expectOutputIs(const Image& image, float gain) {
        ASSERT_EQ(live_->executor().viewport(), glm::ivec2(image.width, image.height));
        Diagnostics frame = live_->executor().renderFrame({}).takeDiagnostics();
        ASSERT_FALSE(hasErrors(frame)) << formatAll(frame);
        Image out = readBack(live_->executor(), "output");
        ASSERT_EQ(out.width, image.width);
        ASSERT_EQ(out.height, image.height);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(out.at(x, y, c), image.at(x, y, c) * gain) << "pixel " << x << ", " << y << " channel " << c;
    }

    bool watches(const fs::path& file) const {
        for (const fs::path& watched : live_->watchedFiles())
            if (fs::equivalent(watched, file)) return true;
        return false;
    }

    ScratchDir dir_;
    std::unique_ptr<LiveWorkspace> live_;
};

TEST_F(LiveInputsGLTest, TheImageSetsTheViewportAndReplacesTheScene) {
    EXPECT_TRUE(watches(dir_ / "shot.exr"));
    expectOutputIs(pattern(3, 2, 0.5f), 2.0f);
    EXPECT_EQ(live_->executor().passProgram("draw"), 0u) << "the pass that drew the scene is culled";
}

TEST_F(LiveInputsGLTest, ASavedImageReplacesOnlyTheInput) {
    const unsigned copyProgram = live_->executor().passProgram("copy");
    ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "shot.exr", pattern(3, 2, 1.25f)));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_FALSE(live_->lastReload().workspaceRebuilt);
    EXPECT_EQ(live_->lastReload().reloadedInputs, std::vector<std::string>{"scene"});
    EXPECT_EQ(live_->executor().passProgram("copy"), copyProgram);
    expectOutputIs(pattern(3, 2, 1.25f), 2.0f);
}

TEST_F(LiveInputsGLTest, AnImageOfAnotherSizeBuildsTheWorkspaceAtThatSize) {
    ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "shot.exr", pattern(5, 3, 0.25f)));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().workspaceRebuilt);
    expectOutputIs(pattern(5, 3, 0.25f), 2.0f);
}

TEST_F(LiveInputsGLTest, AnUnreadableSaveKeepsTheLastImageUntilAGoodOne) {
    { std::ofstream(dir_ / "shot.exr", std::ios::binary) << "not an image"; }
    ASSERT_TRUE(waitForReload());
    ASSERT_FALSE(live_->errors().empty());
    EXPECT_NE(formatAll(live_->errors()).find("shot.exr"), std::string::npos) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().failed);
    expectOutputIs(pattern(3, 2, 0.5f), 2.0f);

    ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "shot.exr", pattern(3, 2, 0.75f)));
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    expectOutputIs(pattern(3, 2, 0.75f), 2.0f);
}

TEST_F(LiveInputsGLTest, AWorkspaceReloadKeepsTheImage) {
    std::string edited = workspaceXml;
    edited.replace(edited.find("value=\"2\""), 9, "value=\"4\"");
    dir_.write("ws.xml", edited);
    ASSERT_TRUE(waitForReload());
    EXPECT_TRUE(live_->errors().empty()) << formatAll(live_->errors());
    EXPECT_TRUE(live_->lastReload().workspaceRebuilt);
    expectOutputIs(pattern(3, 2, 0.5f), 4.0f);
}

TEST_F(LiveInputsGLTest, ADroppedFileBecomesTheInputAndIsWatchedInstead) {
    ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "dropped.exr", pattern(2, 4, 1.5f)));
    Result<void> set = live_->setInput(parseInputArgument((dir_ / "dropped.exr").string()));
    ASSERT_TRUE(set) << formatAll(set.diagnostics());
    ASSERT_EQ(live_->inputs().size(), 1u) << "the dropped file replaces the input's file";
    EXPECT_TRUE(watches(dir_ / "dropped.exr"));
    EXPECT_FALSE(watches(dir_ / "shot.exr"));
    expectOutputIs(pattern(2, 4, 1.5f), 2.0f);

    ASSERT_NO_FATAL_FAILURE(saveAtomically(dir_ / "dropped.exr", pattern(2, 4, 0.125f)));
    ASSERT_TRUE(waitForReload());
    expectOutputIs(pattern(2, 4, 0.125f), 2.0f);
}

TEST_F(LiveInputsGLTest, ADroppedFileThatCannotBeReadChangesNothing) {
    dir_.write("notes.txt", "not an image");
    Result<void> set = live_->setInput(parseInputArgument((dir_ / "notes.txt").string()));
    ASSERT_FALSE(set);
    EXPECT_NE(set.error().find("notes.txt"), std::string::npos) << set.error();
    ASSERT_EQ(live_->inputs().size(), 1u);
    EXPECT_EQ(live_->inputs().front().file, dir_ / "shot.exr");
    EXPECT_TRUE(watches(dir_ / "shot.exr"));
    expectOutputIs(pattern(3, 2, 0.5f), 2.0f);
}

TEST_F(LiveInputsGLTest, ANewViewportSizeResamplesTheImage) {
    ASSERT_TRUE(live_->setViewport({6, 4})) << "3x2 to 6x4";
    EXPECT_EQ(live_->executor().viewport(), glm::ivec2(6, 4));
    Diagnostics frame = live_->executor().renderFrame({}).takeDiagnostics();
    ASSERT_FALSE(hasErrors(frame)) << formatAll(frame);
    Image out = readBack(live_->executor(), "output");
    // A constant channel stays constant under any resampling filter: blue is 0.5 everywhere.
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) EXPECT_FLOAT_EQ(out.at(x, y, 2), 1.0f) << x << ", " << y;
}

}  // namespace
}  // namespace rmfx::test
